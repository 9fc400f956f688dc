; A robot brings crates to regions, by picking and placing or by pushing
; along the surface. Pushing is dearer (3 against 1 + 1), so pick-and-place
; is tried first; whether a crate fits the gripper is left to the geometry.
(define (domain blind5-shove)
  (:requirements :strips :typing :action-costs)
  (:types crate region)
  (:predicates (in ?c - crate ?r - region)
               (holding ?c - crate)
               (free))
  (:functions (total-cost) - number)
  (:action pick
    :parameters (?c - crate ?r - region)
    :precondition (and (in ?c ?r) (free))
    :effect (and (not (in ?c ?r)) (not (free)) (holding ?c)
                 (increase (total-cost) 1)))
  (:action place
    :parameters (?c - crate ?r - region)
    :precondition (holding ?c)
    :effect (and (not (holding ?c)) (free) (in ?c ?r)
                 (increase (total-cost) 1)))
  (:action push
    :parameters (?c - crate ?from - region ?to - region)
    :precondition (and (in ?c ?from) (free))
    :effect (and (not (in ?c ?from)) (in ?c ?to)
                 (increase (total-cost) 3))))
