; KUKA iiwa: a cube from the table onto a cabinet 30 cm high on the other
; side of a 40 cm partition.
(define (problem blind5-p07)
  (:domain blind5-carry)
  (:objects cube - thing
            floor cabinet_top - region)
  (:init (in cube floor) (free))
  (:goal (in cube cabinet_top)))
