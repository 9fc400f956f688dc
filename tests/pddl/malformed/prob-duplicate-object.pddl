(define (problem p1)
  (:domain depots)
  (:objects t1 - truck
            a b - place
            t1 - truck)
  (:init (at t1 a))
  (:goal (at t1 b)))
