; A cubby that opens away from the robot (+x): roofed, walled on the
; robot's side and both flanks. The hand must come round and point back at
; the base; a tall block (not in the goal) stands 2.5 cm outside the mouth.
(define (problem b33-p05)
  (:domain b33-p05)
  (:objects box plug - item box-home mouth aside cubby - spot)
  (:init (at box box-home) (at plug mouth) (handempty))
  (:goal (at box cubby)))
