; Panda: pick/place between spots. No clear/occupied predicate: which spot
; is free, and which object fits where, is left to the geometry.
(define (domain b27-cycle)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types item spot)
  (:predicates (at ?o - item ?s - spot) (holding ?o - item) (busy))
  (:action pick
    :parameters (?o - item ?from - spot)
    :precondition (and (at ?o ?from) (not (busy)))
    :effect (and (not (at ?o ?from)) (holding ?o) (busy)))
  (:action place
    :parameters (?o - item ?to - spot)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (not (busy)) (at ?o ?to))))
