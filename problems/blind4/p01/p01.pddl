; Panda: put a cube from the counter into the middle bay of a shelf board,
; between three bottles.
(define (problem blind4-p01)
  (:domain blind4-carry)
  (:objects cube - thing
            counter bay - region)
  (:init (in cube counter) (free))
  (:goal (in cube bay)))
