; A 5 cm cube into a 6 cm slot between two walls.
(define (problem robust-arm-p03)
  (:domain robust-arm)
  (:objects a - block
            start slot - region)
  (:init (in a start) (handempty)
         (same-surface start slot) (same-surface slot start)
         (= (total-cost) 0))
  (:goal (in a slot))
  (:metric minimize (total-cost)))
