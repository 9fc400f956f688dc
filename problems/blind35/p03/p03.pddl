; blind35 p03 (KUKA iiwa): a 12 x 2 cm bar into a 10.0 x 10.0 cm pad, where
; it fits only along the diagonal (yaw 44.2-45.8 deg); a nub stands in the pad.
; Expected: nub to spare, bar to pad (4 actions).
(define (problem p03)
  (:domain edge-yaw)
  (:objects bar nub - item
            bar-home pad spare - spot)
  (:init (at bar bar-home) (at nub pad) (handempty))
  (:goal (and (at bar pad) (handempty))))
