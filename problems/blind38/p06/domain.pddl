; blind38 p06: pucks carried through a doorway; an ADL goal over all pucks.
(define (domain door-fetch)
  (:requirements :strips :typing :universal-preconditions)
  (:types puck room)
  (:predicates (in ?p - puck ?r - room) (carrying ?p - puck) (empty))
  (:action grab
    :parameters (?p - puck ?r - room)
    :precondition (and (in ?p ?r) (empty))
    :effect (and (carrying ?p) (not (in ?p ?r)) (not (empty))))
  (:action release
    :parameters (?p - puck ?r - room)
    :precondition (carrying ?p)
    :effect (and (in ?p ?r) (empty) (not (carrying ?p)))))
