; blind34 p02: planar disk, typed, with action costs. What may be pushed
; and what may be lifted are static facts the problem sets.
(define (domain exact-cycle)
  (:requirements :strips :typing :negative-preconditions :equality :action-costs)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone)
               (holding ?o - thing)
               (liftable ?o - thing)
               (pushable ?o - thing)
               (hand-full))
  (:functions (total-cost) - number)
  (:action push
    :parameters (?o - thing ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (pushable ?o) (not (hand-full))
                       (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to) (increase (total-cost) 1)))
  (:action grab
    :parameters (?o - thing ?from - zone)
    :precondition (and (at ?o ?from) (liftable ?o) (not (hand-full)))
    :effect (and (not (at ?o ?from)) (holding ?o) (hand-full)
                 (increase (total-cost) 1)))
  (:action drop
    :parameters (?o - thing ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (not (hand-full)) (at ?o ?to)
                 (increase (total-cost) 1))))
