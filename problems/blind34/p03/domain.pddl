; blind34 p03: typed pick/place/stack plus an arm's push, with `clear` and
; static `liftable` / `pushable` (the crate is pushable, not liftable).
(define (domain unload-push-reload)
  (:requirements :strips :typing :equality)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone)
               (on ?o - item ?s - item)
               (clear ?o - item)
               (holding ?o - item)
               (handempty)
               (liftable ?o - item)
               (pushable ?o - item))
  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (clear ?o) (liftable ?o) (handempty))
    :effect (and (not (at ?o ?z)) (not (handempty)) (holding ?o)))
  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (handempty) (not (holding ?o))))
  (:action unstack
    :parameters (?o - item ?s - item)
    :precondition (and (on ?o ?s) (clear ?o) (liftable ?o) (handempty))
    :effect (and (not (on ?o ?s)) (clear ?s) (not (handempty)) (holding ?o)))
  (:action stack
    :parameters (?o - item ?s - item)
    :precondition (and (holding ?o) (clear ?s) (not (= ?o ?s)))
    :effect (and (on ?o ?s) (not (clear ?s)) (handempty) (not (holding ?o))))
  (:action push
    :parameters (?o - item ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (pushable ?o) (clear ?o) (handempty)
                       (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to))))
