; blind17 p03: typed pick / place with one object per spot (Panda).
; (free ?s) keeps two objects out of one spot.
(define (domain restore-scene)
  (:requirements :strips :typing)
  (:types item spot)
  (:predicates (at ?o - item ?s - spot)
               (free ?s - spot)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (free ?s) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?s - spot)
    :precondition (and (holding ?o) (free ?s))
    :effect (and (not (holding ?o)) (not (free ?s)) (handempty) (at ?o ?s))))
