; Carry a block through an L-shaped corridor, 13 cm wide then 19 cm wide,
; into a closed room at its far end.
(define (problem blind2-p06)
  (:domain blind2-planar)
  (:objects a - block
            west room - region)
  (:init (in a west) (handempty))
  (:goal (in a room)))
