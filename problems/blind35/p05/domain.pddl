; blind35 p05/p06: planar disk. The crate may only be pushed, and only
; between the zones marked (push-zone); the puck may only be carried.
(define (domain edge-cone)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone)
               (holding ?o - thing)
               (hand-full)
               (liftable ?o - thing)
               (pushable ?o - thing)
               (push-zone ?z - zone))
  (:action push
    :parameters (?o - thing ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (pushable ?o) (not (hand-full))
                       (push-zone ?from) (push-zone ?to) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)))
  (:action grab
    :parameters (?o - thing ?from - zone)
    :precondition (and (at ?o ?from) (liftable ?o) (not (hand-full)))
    :effect (and (not (at ?o ?from)) (holding ?o) (hand-full)))
  (:action drop
    :parameters (?o - thing ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (not (hand-full)) (at ?o ?to))))
