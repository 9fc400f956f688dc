; A Franka Panda moves blocks between regions of a table, stacks them and
; pushes the ones it cannot lift. The symbolic level says where a block is
; and nothing else: no (clear ...), no capacity, no "fits", no "graspable".
; Whether a region has room, whether a block can be grasped (or only pushed),
; from which side, and whether a tower leaves room for the hand are left to
; the geometry. Pushing is dearer than picking and placing, so a block that
; cannot be lifted is found out geometrically, not by its cost.
(define (domain robust-arm)
  (:requirements :strips :typing :equality :negative-preconditions :action-costs)
  (:types block region)
  (:predicates (in ?b - block ?r - region)
               (on ?b - block ?c - block)
               (holding ?b - block)
               (handempty)
               (same-surface ?r1 - region ?r2 - region))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?b - block ?from - region)
    :precondition (and (in ?b ?from) (handempty))
    :effect (and (not (in ?b ?from)) (not (handempty)) (holding ?b)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?b - block ?to - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (in ?b ?to)
                 (increase (total-cost) 1)))

  (:action unstack
    :parameters (?b - block ?from - block)
    :precondition (and (on ?b ?from) (handempty))
    :effect (and (not (on ?b ?from)) (not (handempty)) (holding ?b)
                 (increase (total-cost) 1)))

  (:action stack
    :parameters (?b - block ?to - block)
    :precondition (and (holding ?b) (not (= ?b ?to)))
    :effect (and (not (holding ?b)) (handempty) (on ?b ?to)
                 (increase (total-cost) 1)))

  (:action push
    :parameters (?b - block ?from - region ?to - region)
    :precondition (and (in ?b ?from) (handempty) (same-surface ?from ?to)
                       (not (= ?from ?to)))
    :effect (and (not (in ?b ?from)) (in ?b ?to)
                 (increase (total-cost) 3))))
