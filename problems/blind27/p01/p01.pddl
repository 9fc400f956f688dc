; A 3-cycle of three different shapes through a buffer only the can fits.
(define (problem b27-p01)
  (:domain b27-cycle)
  (:objects bar cube can - item spot-a spot-b spot-c buffer - spot)
  (:init (at bar spot-a) (at cube spot-b) (at can spot-c))
  (:goal (and (at bar spot-b) (at cube spot-c) (at can spot-a))))
