; Invert a two-block stack: the wide slab starts on the small cube; the goal
; is the cube on the slab, the slab in the goal region.
(define (problem blind2-p03)
  (:domain blind2-stack)
  (:objects slab cube - obj
            start goal - region)
  (:init (in cube start) (on slab cube) (handempty))
  (:goal (and (on cube slab) (in slab goal))))
