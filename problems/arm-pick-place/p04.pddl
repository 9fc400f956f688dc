; The goal region (8 x 8 cm) already holds cube c: it must be moved out
; before a fits. The two-action skeleton is geometrically infeasible.
(define (problem arm-pick-place-p04)
  (:domain arm-pick-place)
  (:objects a c - block
            start goal - region)
  (:init (at a start) (at c goal) (clear a) (clear c) (handempty))
  (:goal (at a goal)))
