; One cube from the right of the robot to a goal region on its left.
(define (problem arm-xarm-p01)
  (:domain arm-xarm)
  (:objects a - block
            start goal - region)
  (:init (at a start) (clear a) (handempty))
  (:goal (at a goal)))
