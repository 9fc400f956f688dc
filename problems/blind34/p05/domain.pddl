; blind34 p05: plain typed pick/place, no `clear`, no occupancy: which
; neighbour is in the way of which grip is left to the geometry.
(define (domain which-to-move)
  (:requirements :strips :typing)
  (:types thing spot)
  (:predicates (at ?o - thing ?s - spot)
               (holding ?o - thing)
               (free))
  (:action take
    :parameters (?o - thing ?s - spot)
    :precondition (and (at ?o ?s) (free))
    :effect (and (not (at ?o ?s)) (not (free)) (holding ?o)))
  (:action put
    :parameters (?o - thing ?s - spot)
    :precondition (holding ?o)
    :effect (and (at ?o ?s) (free) (not (holding ?o)))))
