; A box the gripper cannot hold, pushed sideways.
(define (problem robust-arm-p10)
  (:domain robust-arm)
  (:objects box - block
            start goal - region)
  (:init (in box start) (handempty)
         (same-surface start goal) (same-surface goal start)
         (= (total-cost) 0))
  (:goal (in box goal))
  (:metric minimize (total-cost)))
