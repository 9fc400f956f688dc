; Two cubes into one goal region (15 x 15 cm: room for both).
(define (problem arm-pick-place-p03)
  (:domain arm-pick-place)
  (:objects a b - block
            start goal - region)
  (:init (at a start) (at b start) (clear a) (clear b) (handempty))
  (:goal (and (at a goal) (at b goal))))
