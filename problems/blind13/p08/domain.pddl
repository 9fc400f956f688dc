; blind13 p08: typed, negative preconditions and a negated goal fact. Nothing
; symbolic says a region is occupied: only the geometry knows the stone is in
; the way.
(define (domain xarm-nest)
  (:requirements :strips :typing :negative-preconditions)
  (:types piece area)
  (:predicates (at ?p - piece ?a - area)
               (held ?p - piece)
               (hand-busy))

  (:action pick
    :parameters (?p - piece ?a - area)
    :precondition (and (at ?p ?a) (not (hand-busy)))
    :effect (and (held ?p) (hand-busy) (not (at ?p ?a))))

  (:action place
    :parameters (?p - piece ?a - area)
    :precondition (held ?p)
    :effect (and (at ?p ?a) (not (held ?p)) (not (hand-busy)))))
