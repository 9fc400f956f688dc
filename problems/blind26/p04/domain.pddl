; Planar disk: items are pushed (cost 1) or carried (pick 1 + place 1).
(define (domain b26-pillar-pad)
  (:requirements :strips :typing :equality :negative-preconditions
                 :action-costs)
  (:types item region)
  (:predicates (at ?o - item ?r - region) (holding ?o - item) (handempty)
               (liftable ?o - item))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?o - item ?from ?to - region)
    :precondition (and (at ?o ?from) (handempty) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to) (increase (total-cost) 1)))

  (:action pick
    :parameters (?o - item ?from - region)
    :precondition (and (at ?o ?from) (handempty) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - item ?to - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 1))))
