; A dead-end channel, narrow at its far slot, wide at its near one. y is in
; the far slot and must move one slot forward; x goes to the far slot.
; x fits the far slot only gripped across the channel's length, which needs
; a finger's room in front of it: y put in the near slot first seals it.
; 4 actions look enough; 6 are needed (y parked, x in, y forward).
(define (problem b33-p06)
  (:domain b33-p06)
  (:objects x y - item home far near spare - spot)
  (:init (at x home) (at y far) (handempty))
  (:goal (and (at x far) (at y near))))
