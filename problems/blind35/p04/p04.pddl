; blind35 p04 (KUKA iiwa): a 12 x 2 cm bar into a 9.7 x 9.7 cm pad, where
; it fits at no yaw (its least square span, at 45 deg, is 9.90 cm); a nub stands in the pad.
; Expected: unsolvable, proved: the bar fits the pad at no yaw.
(define (problem p04)
  (:domain edge-yaw)
  (:objects bar nub - item
            bar-home pad spare - spot)
  (:init (at bar bar-home) (at nub pad) (handempty))
  (:goal (and (at bar pad) (handempty))))
