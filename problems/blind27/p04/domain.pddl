; Planar disk: items are pushed (cost 1) or, if liftable, carried
; (pick 1 + place 1).
(define (domain b27-doorway)
  (:requirements :strips :typing :equality :negative-preconditions
                 :action-costs)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone) (holding ?o - item) (free)
               (liftable ?o - item))
  (:functions (total-cost) - number)
  (:action push
    :parameters (?o - item ?from ?to - zone)
    :precondition (and (at ?o ?from) (free) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to) (increase (total-cost) 1)))
  (:action pick
    :parameters (?o - item ?from - zone)
    :precondition (and (at ?o ?from) (free) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (free)) (holding ?o)
                 (increase (total-cost) 1)))
  (:action place
    :parameters (?o - item ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (free) (at ?o ?to)
                 (increase (total-cost) 1))))
