; Stack a on b; b stands turned 30 degrees.
(define (problem robust-arm-p11)
  (:domain robust-arm)
  (:objects a b - block
            start - region)
  (:init (in a start) (in b start) (handempty)
         (= (total-cost) 0))
  (:goal (on a b))
  (:metric minimize (total-cost)))
