; KUKA iiwa: a goal of three kinds at once: one block on another, a second
; in a zone, the hand empty, and a third block left where it is.
(define (problem blind6-p03)
  (:domain blind6-stacks)
  (:objects slab cube can - block
            field bay - zone)
  (:init (in slab field) (in cube field) (in can field)
         (clear slab) (clear cube) (clear can) (hand-empty))
  (:goal (and (on cube slab) (in can bay) (hand-empty) (in slab field)
              (clear cube))))
