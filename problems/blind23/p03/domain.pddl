; blind23 p03: typed hierarchy (`can - item`), :negative-preconditions
; (`(not (busy))` instead of handempty), unit costs. Every can may be
; pushed or picked; the domain does not say which cans stand in the way.
(define (domain can-row)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types item zone - object
          can - item)
  (:predicates (at ?o - item ?z - zone)
               (holding ?o - item)
               (busy))

  (:action push
    :parameters (?o - can ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (not (busy)) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)))

  (:action pick
    :parameters (?o - can ?z - zone)
    :precondition (and (at ?o ?z) (not (busy)))
    :effect (and (not (at ?o ?z)) (busy) (holding ?o)))

  (:action place
    :parameters (?o - can ?z - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (not (busy)) (at ?o ?z))))
