(define (problem p1)
  (:domain depots)
  (:objects t1 - truck
            a b - place)
  (:init (at t1 a))
  (:goal (at ?t b)))
