;; blind10 p06: blocks on spots and on each other. A block is plucked
;; from a spot or unpiled from a block when nothing is on it, and dropped
;; on a spot or piled on a bare block.
(define (domain blind10-pile)
  (:requirements :strips :typing :equality :negative-preconditions)
  (:types block spot)
  (:predicates (placed ?b - block ?s - spot)
               (atop ?b - block ?c - block)
               (bare ?b - block)
               (grasping ?b - block)
               (empty-hand))
  (:action pluck
    :parameters (?b - block ?s - spot)
    :precondition (and (placed ?b ?s) (bare ?b) (empty-hand))
    :effect (and (not (placed ?b ?s)) (not (empty-hand)) (grasping ?b)))
  (:action unpile
    :parameters (?b - block ?c - block)
    :precondition (and (atop ?b ?c) (bare ?b) (empty-hand))
    :effect (and (not (atop ?b ?c)) (not (empty-hand)) (grasping ?b) (bare ?c)))
  (:action drop
    :parameters (?b - block ?s - spot)
    :precondition (grasping ?b)
    :effect (and (not (grasping ?b)) (empty-hand) (placed ?b ?s)))
  (:action pile
    :parameters (?b - block ?c - block)
    :precondition (and (grasping ?b) (bare ?c) (not (= ?b ?c)))
    :effect (and (not (grasping ?b)) (empty-hand) (atop ?b ?c) (not (bare ?c)))))
