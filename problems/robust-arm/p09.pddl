; A crate the gripper cannot hold, pushed away from the robot.
(define (problem robust-arm-p09)
  (:domain robust-arm)
  (:objects crate - block
            start goal - region)
  (:init (in crate start) (handempty)
         (same-surface start goal) (same-surface goal start)
         (= (total-cost) 0))
  (:goal (in crate goal))
  (:metric minimize (total-cost)))
