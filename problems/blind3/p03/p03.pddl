; Planar disk: carry a bar through a doorway in a wall that splits the bench.
(define (problem blind3-p03)
  (:domain blind3-pick-place)
  (:objects bar - obj
            west east - region)
  (:init (at bar west) (handempty))
  (:goal (at bar east)))
