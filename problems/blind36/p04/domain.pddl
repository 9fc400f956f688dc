; blind36 p04: typed pick-and-place; the problem's goal is negative and universal.
(define (domain unload)
  (:requirements :strips :typing :negative-preconditions :universal-preconditions)
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
