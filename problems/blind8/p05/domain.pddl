;; A table-top arm that can push what it cannot lift. Pushing costs more
;; than a pick and a place together would.
(define (domain blind8-push-pick)
  (:requirements :strips :typing :equality :action-costs)
  (:types obj zone)
  (:predicates (at ?o - obj ?z - zone)
               (holding ?o - obj)
               (handempty)
               (liftable ?o - obj))
  (:functions (total-cost) - number)
  (:action push
    :parameters (?o - obj ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (handempty) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to) (increase (total-cost) 3)))
  (:action pick
    :parameters (?o - obj ?from - zone)
    :precondition (and (at ?o ?from) (handempty) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))
  (:action place
    :parameters (?o - obj ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 1))))
