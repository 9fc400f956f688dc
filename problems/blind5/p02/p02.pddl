; Planar robot: sort four blocks from one row into four goal pads, each
; block to a pad that is not in front of it (8 actions).
(define (problem blind5-p02)
  (:domain blind5-carry)
  (:objects b1 b2 b3 b4 - thing
            row g1 g2 g3 g4 - region)
  (:init (in b1 row) (in b2 row) (in b3 row) (in b4 row) (free))
  (:goal (and (in b1 g3) (in b2 g1) (in b3 g4) (in b4 g2))))
