; pen-3: the goal region already holds three blockers of different sizes; the
; domain has no `clear` and no capacity, so only geometry says they must leave.
; Expected: 8 actions (three blockers out to the yard, then t in).
(define (problem robust-pen-3)
  (:domain robust-planar)
  (:objects t b1 b2 b3 - block
            yard pen - region)
  (:init (in t yard) (in b1 pen) (in b2 pen) (in b3 pen) (handempty))
  (:goal (in t pen)))
