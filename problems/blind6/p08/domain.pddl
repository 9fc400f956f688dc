; Carry parts between zones. Only where a part is is recorded; what is in
; the way is left to the geometry.
(define (domain blind6-carry)
  (:requirements :strips :typing)
  (:types part zone)
  (:predicates (in ?p - part ?z - zone)
               (holding ?p - part)
               (hand-empty))
  (:action pick
    :parameters (?p - part ?z - zone)
    :precondition (and (in ?p ?z) (hand-empty))
    :effect (and (not (in ?p ?z)) (not (hand-empty)) (holding ?p)))
  (:action place
    :parameters (?p - part ?z - zone)
    :precondition (holding ?p)
    :effect (and (not (holding ?p)) (hand-empty) (in ?p ?z))))
