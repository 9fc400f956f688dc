(define (problem p1)
  (:domain depots)
  (:objects t1 - truck
            a - place
            box - (either cargo place))
  (:init (at t1 a))
  (:goal (in box t1)))
