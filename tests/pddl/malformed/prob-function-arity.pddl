(define (problem p1)
  (:domain depots)
  (:objects t1 - truck
            a b - place)
  (:init (at t1 a)
         (= (distance a) 4))
  (:goal (at t1 b)))
