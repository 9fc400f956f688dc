; A cylinder into a slot that only the hand, turned across it, fits into.
(define (problem robust-arm-p04)
  (:domain robust-arm)
  (:objects a - block
            start slot - region)
  (:init (in a start) (handempty)
         (same-surface start slot) (same-surface slot start)
         (= (total-cost) 0))
  (:goal (in a slot))
  (:metric minimize (total-cost)))
