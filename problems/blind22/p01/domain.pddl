; blind22 p01: untyped STRIPS with type predicates and one negative
; precondition (the hand is free when `busy` is false). Nothing says how
; much a spot holds: two items may share one spot, and only the geometry
; says whether they fit side by side.
(define (domain pack-pair)
  (:requirements :strips :negative-preconditions)
  (:predicates (item ?o) (spot ?s) (at ?o ?s) (holding ?o) (busy))

  (:action pick
    :parameters (?o ?s)
    :precondition (and (item ?o) (spot ?s) (at ?o ?s) (not (busy)))
    :effect (and (not (at ?o ?s)) (holding ?o) (busy)))

  (:action place
    :parameters (?o ?s)
    :precondition (and (item ?o) (spot ?s) (holding ?o))
    :effect (and (at ?o ?s) (not (holding ?o)) (not (busy)))))
