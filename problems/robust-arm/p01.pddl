; Block a into the goal region, which b and c occupy. The domain has no
; (clear ...) and no capacity: only the geometry says that b and c are in the way.
(define (problem robust-arm-p01)
  (:domain robust-arm)
  (:objects a b c - block
            start goal side - region)
  (:init (in a start) (in b goal) (in c goal) (handempty)
         (same-surface start goal) (same-surface goal start)
         (same-surface start side) (same-surface side start)
         (same-surface goal side) (same-surface side goal)
         (= (total-cost) 0))
  (:goal (in a goal))
  (:metric minimize (total-cost)))
