; blind33 p04: one arm, pick/place between spots. No occupancy predicate:
; which spot is free, which grip fits, and in what order, is the geometry's.
(define (domain b33-p04)
  (:requirements :strips :typing)
  (:types item spot)
  (:predicates (at ?o - item ?s - spot) (holding ?o - item) (handempty))
  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (holding ?o) (not (at ?o ?s)) (not (handempty))))
  (:action place
    :parameters (?o - item ?s - spot)
    :precondition (holding ?o)
    :effect (and (at ?o ?s) (handempty) (not (holding ?o)))))
