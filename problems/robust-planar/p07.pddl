; row packing: four blocks of four sizes into one region they fill to 90 % of
; its length. Expected: 8 actions.
(define (problem robust-row-pack)
  (:domain robust-planar)
  (:objects a b c d - block
            depot row - region)
  (:init (in a depot) (in b depot) (in c depot) (in d depot) (handempty))
  (:goal (and (in a row) (in b row) (in c row) (in d row))))
