; Panda: one cube from one clearing to another through a cluttered table
; (twelve fixed obstacles, 4 to 30 cm tall).
(define (problem blind6-p05)
  (:domain blind6-carry)
  (:objects cube - part
            src dst - zone)
  (:init (in cube src) (hand-empty))
  (:goal (in cube dst)))
