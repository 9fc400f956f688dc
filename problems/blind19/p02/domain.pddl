; blind19 p02: push and stack, typed, with action costs (push 2, pick /
; place / stack 1). Only pushable items are pushed; nothing says which
; item the gripper can hold (the drum is too wide: geometry proves it) nor
; where a push can go (a wall known only to the scene).
(define (domain drum-route)
  (:requirements :strips :typing :equality :negative-preconditions
                 :action-costs)
  (:types item region)
  (:predicates (at ?o - item ?r - region)
               (on ?o - item ?u - item)
               (clear ?o - item)
               (pushable ?o - item)
               (holding ?o - item)
               (handempty))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?o - item ?from ?to - region)
    :precondition (and (at ?o ?from) (clear ?o) (handempty) (pushable ?o)
                       (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)
                 (increase (total-cost) 2)))

  (:action pick
    :parameters (?o - item ?r - region)
    :precondition (and (at ?o ?r) (clear ?o) (handempty))
    :effect (and (not (at ?o ?r)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - item ?r - region)
    :precondition (holding ?o)
    :effect (and (at ?o ?r) (not (holding ?o)) (handempty)
                 (increase (total-cost) 1)))

  (:action stack
    :parameters (?o - item ?u - item)
    :precondition (and (holding ?o) (clear ?u) (not (= ?o ?u)))
    :effect (and (on ?o ?u) (not (clear ?u)) (not (holding ?o)) (handempty)
                 (increase (total-cost) 1))))
