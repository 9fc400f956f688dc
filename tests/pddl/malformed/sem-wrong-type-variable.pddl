(define (domain d)
  (:requirements :typing)
  (:types truck place)
  (:predicates (at ?t - truck ?p - place))
  (:action a
    :parameters (?t - truck ?p - place)
    :precondition (at ?p ?t)
    :effect (at ?t ?p)))
