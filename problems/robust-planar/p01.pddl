; pen-2: the goal region already holds two blockers; the domain has no `clear`
; and no capacity, so only geometry says they must leave first.
; Expected: 6 actions (both blockers out to the yard, then t in).
(define (problem robust-pen-2)
  (:domain robust-planar)
  (:objects t b1 b2 - block
            yard pen - region)
  (:init (in t yard) (in b1 pen) (in b2 pen) (handempty))
  (:goal (in t pen)))
