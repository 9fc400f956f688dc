; The cube goes into the left slot against the wall, right under the arm's
; mount; the can standing there goes into either bin.
(define (problem b29-p02)
  (:domain b29-wallarm)
  (:objects cube can slot-l slot-r cube-home bin-a bin-b)
  (:init (item cube) (item can)
         (spot slot-l) (spot slot-r) (spot cube-home) (spot bin-a) (spot bin-b)
         (at can slot-l) (at cube cube-home) (hand-empty))
  (:goal (and (at cube slot-l)
              (or (at can bin-a) (at can bin-b))
              (hand-empty))))
