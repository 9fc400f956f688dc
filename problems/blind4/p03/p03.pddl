; Panda: build slab - cube - can (slab at the bottom) in the goal region from
; three pieces of three shapes lying about the bench, each turned its own way.
(define (problem blind4-p03)
  (:domain blind4-tower)
  (:objects slab cube can - piece
            bench goal - region)
  (:init (in slab bench) (in cube bench) (in can bench)
         (top slab) (top cube) (top can) (free))
  (:goal (and (in slab goal) (on cube slab) (on can cube))))
