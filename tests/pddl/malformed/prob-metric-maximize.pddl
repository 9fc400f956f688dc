(define (problem p1)
  (:domain depots)
  (:objects t1 - truck
            a b - place)
  (:init (at t1 a) (road a b)
         (= (total-cost) 0) (= (distance a b) 3))
  (:goal (at t1 b))
  (:metric maximize (total-cost)))
