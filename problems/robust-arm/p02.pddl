; Block a into the goal region, whose corners hold b, c and d.
(define (problem robust-arm-p02)
  (:domain robust-arm)
  (:objects a b c d - block
            start goal side - region)
  (:init (in a start) (in b goal) (in c goal) (in d goal) (handempty)
         (same-surface start goal) (same-surface goal start)
         (same-surface start side) (same-surface side start)
         (same-surface goal side) (same-surface side goal)
         (= (total-cost) 0))
  (:goal (in a goal))
  (:metric minimize (total-cost)))
