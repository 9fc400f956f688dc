; Grip-axis regrasp: the block's ends are walled at the start (fingers only
; on its long faces), its long faces are walled at the goal (fingers only on
; its ends). No single grip serves both: put it down and take it again.
(define (problem b33-p01)
  (:domain b33-p01)
  (:objects block - item start trough spare-a spare-b - spot)
  (:init (at block start) (handempty))
  (:goal (at block trough)))
