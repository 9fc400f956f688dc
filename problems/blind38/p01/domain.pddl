; blind38 p01: typed pick/place without occupancy; what is in the way is left to geometry.
(define (domain shelf-tidy)
  (:requirements :strips :typing)
  (:types item region)
  (:predicates (at ?o - item ?r - region) (holding ?o - item) (handempty))
  (:action pick
    :parameters (?o - item ?r - region)
    :precondition (and (at ?o ?r) (handempty))
    :effect (and (holding ?o) (not (at ?o ?r)) (not (handempty))))
  (:action place
    :parameters (?o - item ?r - region)
    :precondition (holding ?o)
    :effect (and (at ?o ?r) (handempty) (not (holding ?o)))))
