; blind16 p02: planar pick / place with one object per spot. A spot is
; empty or holds exactly one object; a place needs an empty spot.
(define (domain planar-shuffle)
  (:requirements :strips :typing)
  (:types puck spot)
  (:predicates (at ?o - puck ?s - spot)
               (empty ?s - spot)
               (holding ?o - puck)
               (handempty))

  (:action pick
    :parameters (?o - puck ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (empty ?s)
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - puck ?s - spot)
    :precondition (and (holding ?o) (empty ?s))
    :effect (and (not (holding ?o)) (handempty)
                 (at ?o ?s) (not (empty ?s)))))
