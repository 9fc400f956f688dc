; Panda: hand a cube from the front right of the table to a zone behind the
; robot, on its left (2 actions, a 181 deg turn of the base joint).
(define (problem blind6-p07)
  (:domain blind6-carry)
  (:objects cube - part
            front back - zone)
  (:init (in cube front) (hand-empty))
  (:goal (in cube back)))
