; blind20 p02: untyped STRIPS with unary "type" predicates, a negative
; precondition on the hand and an `imply` goal. Places hold any number of
; parts: nothing symbolic says the rail takes three cubes only side by side.
(define (domain rail)
  (:requirements :strips :negative-preconditions
                 :disjunctive-preconditions :universal-preconditions)
  (:predicates (part ?x) (place ?p) (red ?x)
               (at ?x ?p) (holding ?x) (busy))

  (:action pick
    :parameters (?x ?p)
    :precondition (and (part ?x) (place ?p) (at ?x ?p) (not (busy)))
    :effect (and (not (at ?x ?p)) (holding ?x) (busy)))

  (:action put
    :parameters (?x ?p)
    :precondition (and (holding ?x) (place ?p))
    :effect (and (at ?x ?p) (not (holding ?x)) (not (busy)))))
