; blind23 p02: typed push / pick / place (KUKA iiwa) with :action-costs: a
; push costs 2, a pick or a place 1, so the single pick and place (2) and
; the single push (2) come before two pushes (4). Any zone to any other:
; nothing in the PDDL says the crate cannot be gripped or which way a push
; can go; the geometry must find both out.
(define (domain crate-two-pushes)
  (:requirements :strips :typing :equality :action-costs)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone)
               (holding ?o - thing)
               (handempty))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?o - thing ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (handempty) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)
                 (increase (total-cost) 2)))

  (:action pick
    :parameters (?o - thing ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (not (at ?o ?z)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - thing ?z - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?z)
                 (increase (total-cost) 1))))
