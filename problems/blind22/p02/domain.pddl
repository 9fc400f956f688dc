; blind22 p02: typed, with a derived predicate: an item is `in-bin` when it
; is at a spot that lies inside the bin. The goal is negative: the tin must
; no longer be in the bin, wherever it goes.
(define (domain bin-cage)
  (:requirements :strips :typing :negative-preconditions
                 :derived-predicates :existential-preconditions)
  (:types item spot)
  (:predicates (at ?o - item ?s - spot)
               (inside ?s - spot)
               (in-bin ?o - item)
               (holding ?o - item)
               (handempty))

  (:derived (in-bin ?o - item)
    (exists (?s - spot) (and (inside ?s) (at ?o ?s))))

  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?s - spot)
    :precondition (holding ?o)
    :effect (and (at ?o ?s) (not (holding ?o)) (handempty))))
