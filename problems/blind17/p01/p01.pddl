; blind17 p01: swap levels. The cube on the low bench goes up onto the
; 20 cm counter; the can on the counter comes down to the bench.
; Expected: 4 actions, cost 4, either object first.
(define (problem p01)
  (:domain two-levels)
  (:objects cube - cube can - can
            bench-a bench-b - low
            counter-a counter-b - high)
  (:init (at cube bench-a) (at can counter-b) (handempty))
  (:goal (and (at cube counter-a) (at can bench-b))))
