; pen-k2: 2 blockers in the goal region, same layout as the rest of the pen-k family.
; Expected: 6 actions (each blocker out to the yard, then t in).
(define (problem robust-pen-k2)
  (:domain robust-planar)
  (:objects t b1 b2 - block
            yard pen - region)
  (:init (in t yard) (in b1 pen) (in b2 pen) (handempty))
  (:goal (in t pen)))
