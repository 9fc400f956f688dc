; blind36 p03: shelving with capacity-one spots (free) and open surfaces.
(define (domain shelving)
  (:requirements :strips :typing)
  (:types item place - object
          spot surface - place)
  (:predicates (at ?o - item ?p - place)
               (holding ?o - item)
               (handempty)
               (free ?s - spot))
  (:action take-from-spot
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (holding ?o) (free ?s) (not (at ?o ?s)) (not (handempty))))
  (:action take-from-surface
    :parameters (?o - item ?p - surface)
    :precondition (and (at ?o ?p) (handempty))
    :effect (and (holding ?o) (not (at ?o ?p)) (not (handempty))))
  (:action put-in-spot
    :parameters (?o - item ?s - spot)
    :precondition (and (holding ?o) (free ?s))
    :effect (and (at ?o ?s) (handempty) (not (free ?s)) (not (holding ?o))))
  (:action put-on-surface
    :parameters (?o - item ?p - surface)
    :precondition (holding ?o)
    :effect (and (at ?o ?p) (handempty) (not (holding ?o)))))
