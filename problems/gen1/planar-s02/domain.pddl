; gen1 planar: a copy of domains/planar-push: a planar disk pushes an item
; over one surface, or picks (liftable items only) and places it.
(define (domain gen1-planar)
  (:requirements :strips :typing :action-costs)
  (:types item region surface)
  (:predicates (at ?o - item ?r - region)
               (holding ?o - item)
               (handempty)
               (liftable ?o - item)
               (region-on ?r - region ?s - surface))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?o - item ?from - region ?to - region ?s - surface)
    :precondition (and (at ?o ?from) (handempty)
                       (region-on ?from ?s) (region-on ?to ?s))
    :effect (and (not (at ?o ?from)) (at ?o ?to)
                 (increase (total-cost) 2)))

  (:action pick
    :parameters (?o - item ?from - region)
    :precondition (and (at ?o ?from) (handempty) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 2)))

  (:action place
    :parameters (?o - item ?to - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 2))))
