; Occlusion-aware sensing: a fixed camera must see the target before it
; may be delivered. Anything standing in the sightline occludes it, and so
; does the arm unless it is parked (an empty-handed move over the park
; zone; any pick unparks it). Typed, derived predicates (exists, a derived
; predicate under not), negative preconditions.
(define (domain b28-lookout)
  (:requirements :strips :typing :negative-preconditions
                 :derived-predicates :existential-preconditions)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone) (holding ?o - thing) (hand-empty)
               (parked) (park-zone ?z - zone) (sightline ?z - zone)
               (view-spot ?z - zone) (inspected ?o - thing)
               (occluded) (view-clear))

  (:derived (occluded)
    (exists (?o - thing ?z - zone) (and (sightline ?z) (at ?o ?z))))

  (:derived (view-clear)
    (and (parked) (not (occluded))))

  (:action pick
    :parameters (?o - thing ?z - zone)
    :precondition (and (at ?o ?z) (hand-empty))
    :effect (and (not (at ?o ?z)) (holding ?o) (not (hand-empty))
                 (not (parked))))

  (:action place
    :parameters (?o - thing ?z - zone)
    :precondition (and (holding ?o) (not (sightline ?z)) (not (park-zone ?z)))
    :effect (and (at ?o ?z) (hand-empty) (not (holding ?o))))

  (:action park
    :parameters (?z - zone)
    :precondition (and (hand-empty) (park-zone ?z) (not (parked)))
    :effect (parked))

  (:action look
    :parameters (?o - thing ?z - zone)
    :precondition (and (at ?o ?z) (view-spot ?z) (view-clear)
                       (not (inspected ?o)))
    :effect (inspected ?o)))
