; blind15 p06: typed planar push and pick with action costs (push 2, pick 1,
; place 1). Only liftable things can be picked; anything can be pushed.
(define (domain planar-corridor)
  (:requirements :strips :typing :action-costs :equality)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone)
               (holding ?o - thing)
               (handempty)
               (liftable ?o - thing))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?o - thing ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (handempty) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)
                 (increase (total-cost) 2)))

  (:action pick
    :parameters (?o - thing ?from - zone)
    :precondition (and (at ?o ?from) (handempty) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - thing ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 1))))
