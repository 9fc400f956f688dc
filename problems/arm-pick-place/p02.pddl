; p01 with a 30 cm wall between the start and the goal: the same two
; actions, but the carrying motion must go over (or around) the wall.
(define (problem arm-pick-place-p02)
  (:domain arm-pick-place)
  (:objects a - block
            start goal - region)
  (:init (at a start) (clear a) (handempty))
  (:goal (at a goal)))
