; blind37 p03: task A with derived predicates, negative preconditions, an exists goal,
; and a place `on` the dais body instead of a region.
(define (domain tower-derived)
  (:requirements :strips :typing :negative-preconditions :equality
                 :derived-predicates :existential-preconditions)
  (:types piece stand zone - support support)
  (:predicates (on ?p - piece ?s - support)
               (holding ?p - piece)
               (covered ?s - support)
               (hand-busy))
  (:derived (covered ?s - support) (exists (?q - piece) (on ?q ?s)))
  (:derived (hand-busy) (exists (?q - piece) (holding ?q)))
  (:action lift
    :parameters (?p - piece ?s - support)
    :precondition (and (on ?p ?s) (not (covered ?p)) (not (hand-busy)))
    :effect (and (holding ?p) (not (on ?p ?s))))
  (:action lower
    :parameters (?p - piece ?s - support)
    :precondition (and (holding ?p) (not (= ?p ?s)) (not (covered ?s)))
    :effect (and (on ?p ?s) (not (holding ?p)))))
