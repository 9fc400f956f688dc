(define (problem p1)
  (:domain depots)
  (:objects t1 - truk
            a b - place)
  (:init (at t1 a))
  (:goal (at t1 b)))
