; blind37 p05: task B typed, no occupancy, other names, action costs (lift 2, set 1).
(define (domain bay-typed)
  (:requirements :strips :typing :action-costs)
  (:types crate zone)
  (:predicates (in ?c - crate ?z - zone) (gripping ?c - crate) (idle))
  (:functions (total-cost) - number)
  (:action lift
    :parameters (?c - crate ?z - zone)
    :precondition (and (in ?c ?z) (idle))
    :effect (and (gripping ?c) (not (in ?c ?z)) (not (idle)) (increase (total-cost) 2)))
  (:action set
    :parameters (?c - crate ?z - zone)
    :precondition (gripping ?c)
    :effect (and (in ?c ?z) (idle) (not (gripping ?c)) (increase (total-cost) 1))))
