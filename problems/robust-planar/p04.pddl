; slot: carry a 14 cm wide plank lengthwise through a 15 cm slot, 50 cm long.
; Expected: 2 actions.
(define (problem robust-slot)
  (:domain robust-planar)
  (:objects plank - block
            east west-goal - region)
  (:init (in plank east) (handempty))
  (:goal (in plank west-goal)))
