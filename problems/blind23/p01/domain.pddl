; blind23 p01: typed push / pick / place (Panda) with static facts: a push
; may only follow a chute (`(slide ?from ?to)`), a pick only happens where
; the hand may take things (`(pickable ?z)`: not in the chute, whose kerb
; and feeder leave no room for the fingers in the factory this stands for).
; Unit costs, :equality (no push into the zone the object is in).
(define (domain chute-push-pick)
  (:requirements :strips :typing :equality)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone)
               (holding ?o - item)
               (handempty)
               (slide ?from - zone ?to - zone)
               (pickable ?z - zone))

  (:action push
    :parameters (?o - item ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (handempty) (slide ?from ?to)
                       (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)))

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty) (pickable ?z))
    :effect (and (not (at ?o ?z)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?z))))
