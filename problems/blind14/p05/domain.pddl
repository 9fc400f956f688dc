; blind14 p05: a planar disk in two rooms joined by a doorway. A crate
; that may not be lifted is pushed through the doorway; a box is picked,
; carried through and placed. Pushing costs 2, a pick or a place 1: the
; box costs 2 carried and 2 pushed in one go, but that one push from its
; home to the shelf lies outside every face's friction cone (two pushes
; cost 4), so the expected plan mixes one push and one pick and place
; (cost 4).
(define (domain planar-rooms)
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
