; blind16 p01: typed push / pick / place (KUKA iiwa). Only pushable
; things may be pushed, only liftable things picked. Unit costs.
(define (domain kuka-push-then-pick)
  (:requirements :strips :typing :equality)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone)
               (holding ?o - thing)
               (handempty)
               (liftable ?o - thing)
               (pushable ?o - thing))

  (:action push
    :parameters (?o - thing ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (handempty) (pushable ?o)
                       (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)))

  (:action pick
    :parameters (?o - thing ?from - zone)
    :precondition (and (at ?o ?from) (handempty) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - thing ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to))))
