; slot packing: three blocks into a walled bay they fill to 90 % of its length.
; Expected: 6 actions, the first block placed at the far end.
(define (problem robust-slot-pack)
  (:domain robust-planar)
  (:objects a b c - block
            table bay - region)
  (:init (in a table) (in b table) (in c table) (handempty))
  (:goal (and (in a bay) (in b bay) (in c bay))))
