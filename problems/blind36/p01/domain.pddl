; blind36 p01: a plain typed pick-and-place domain, no `clear`, no occupancy:
; what is in the way is left to the geometry.
(define (domain tidy)
  (:requirements :strips :typing)
  (:types item region)
  (:predicates (at ?o - item ?r - region)
               (holding ?o - item)
               (handempty))
  (:action pick
    :parameters (?o - item ?r - region)
    :precondition (and (at ?o ?r) (handempty))
    :effect (and (holding ?o) (not (at ?o ?r)) (not (handempty))))
  (:action place
    :parameters (?o - item ?r - region)
    :precondition (holding ?o)
    :effect (and (at ?o ?r) (handempty) (not (holding ?o)))))
