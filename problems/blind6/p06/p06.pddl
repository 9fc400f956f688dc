; Planar robot, pushes only: block a goes diagonally, beyond the friction
; cone of every face, so it needs two pushes (east then north: the other way
; round is walled); block b needs one push south (3 actions).
(define (problem blind6-p06)
  (:domain blind6-shove)
  (:objects a b - block
            a0 ag via-e via-n b0 bg - zone)
  (:init (in a a0) (in b b0))
  (:goal (and (in a ag) (in b bg))))
