; blind35 p01/p02: plain typed pick and place. No occupancy facts: what is
; in the way is the geometry's to find.
(define (domain edge-width)
  (:requirements :strips :typing)
  (:types item spot)
  (:predicates (at ?o - item ?s - spot)
               (holding ?o - item)
               (handempty))
  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (handempty)) (holding ?o)))
  (:action place
    :parameters (?o - item ?s - spot)
    :precondition (holding ?o)
    :effect (and (at ?o ?s) (handempty) (not (holding ?o)))))
