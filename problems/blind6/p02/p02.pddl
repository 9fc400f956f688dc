; xArm6: a stack of two cubes on a raised platform is taken apart and
; rebuilt upside down on the table: the upper cube goes to the mat, the
; lower one on top of it (4 actions).
(define (problem blind6-p02)
  (:domain blind6-stacks)
  (:objects lower upper - block
            ledge mat - zone)
  (:init (in lower ledge) (on upper lower) (clear upper) (hand-empty))
  (:goal (and (in upper mat) (on lower upper))))
