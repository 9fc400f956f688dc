; pen-k3: 3 blockers in the goal region, same layout as the rest of the pen-k family.
; Expected: 8 actions (each blocker out to the yard, then t in).
(define (problem robust-pen-k3)
  (:domain robust-planar)
  (:objects t b1 b2 b3 - block
            yard pen - region)
  (:init (in t yard) (in b1 pen) (in b2 pen) (in b3 pen) (handempty))
  (:goal (in t pen)))
