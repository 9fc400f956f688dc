; blind25 p01: the tray (with the mug standing on it) must end in `goal`,
; the mug still on it. Symbolically the tray carries the mug (2 actions);
; the geometry should refuse to lift a tray with a mug on it.
; Cheapest symbolic (2): (pick-tray tray tray-home) (place-tray tray goal)
; Expected (6): (unstack-cup mug tray tray-home) (put-cup mug side)
;   (pick-tray tray tray-home) (place-tray tray goal)
;   (pick-cup mug side) (stack-cup mug tray goal)
(define (problem p01)
  (:domain tray-ride)
  (:objects tray - tray
            mug - cup
            tray-home goal side - zone)
  (:init (at tray tray-home) (on mug tray) (at mug tray-home) (handempty))
  (:goal (and (at tray goal) (on mug tray) (handempty))))
