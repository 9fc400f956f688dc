; pen-k1: 1 blocker in the goal region, same layout as the rest of the pen-k family.
; Expected: 4 actions (each blocker out to the yard, then t in).
(define (problem robust-pen-k1)
  (:domain robust-planar)
  (:objects t b1 - block
            yard pen - region)
  (:init (in t yard) (in b1 pen) (handempty))
  (:goal (in t pen)))
