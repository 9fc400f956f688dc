; blind18 p06: typed pick / place whose occupancy is a derived predicate,
; (occupied ?s) <- some item is in ?s, used negatively by place.
(define (domain cage-swap)
  (:requirements :strips :typing :negative-preconditions
                 :derived-predicates :existential-preconditions)
  (:types item spot)
  (:predicates (in ?o - item ?s - spot)
               (occupied ?s - spot)
               (holding ?o - item)
               (handempty))

  (:derived (occupied ?s - spot)
    (exists (?o - item) (in ?o ?s)))

  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (in ?o ?s) (handempty))
    :effect (and (not (in ?o ?s)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?s - spot)
    :precondition (and (holding ?o) (not (occupied ?s)))
    :effect (and (in ?o ?s) (not (holding ?o)) (handempty))))
