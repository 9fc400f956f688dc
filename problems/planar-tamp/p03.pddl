; PDDLStream's cooking variant: take a from the shelf to the stove, cook it
; there (symbolic), and bring it back to the table; b stays on the shelf.
(define (problem planar-tamp-cook)
  (:domain planar-tamp)
  (:objects a b - block
            shelf table stove - region)
  (:init (at a shelf) (at b shelf) (handempty) (is-stove stove))
  (:goal (and (cooked a) (at a table))))
