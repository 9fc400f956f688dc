(define (problem p1)
  (:domain depots)
  (:objects t1 - truck
            a b - place)
  (:init (at t1 a) (road a b)
         (at 10 (road b a)))
  (:goal (at t1 b)))
