; between: slide b into the 8.4 cm gap between a and c on the shelf.
; Expected: 2 actions.
(define (problem robust-between)
  (:domain robust-planar)
  (:objects a b c - block
            table shelf - region)
  (:init (in a shelf) (in c shelf) (in b table) (handempty))
  (:goal (and (in a shelf) (in b shelf) (in c shelf))))
