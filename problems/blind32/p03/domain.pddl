; Blocks on spots of a table, each spot holding at most one block, and
; blocks that may be stacked on one another. A spot is free or not.
(define (domain spots-and-stacks)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types block spot)
  (:predicates (at ?b - block ?s - spot)
               (on ?b - block ?c - block)
               (free ?s - spot)
               (clear ?b - block)
               (holding ?b - block)
               (handempty))
  (:action pick
    :parameters (?b - block ?s - spot)
    :precondition (and (at ?b ?s) (clear ?b) (handempty))
    :effect (and (not (at ?b ?s)) (free ?s) (not (handempty)) (holding ?b)))
  (:action place
    :parameters (?b - block ?s - spot)
    :precondition (and (holding ?b) (free ?s))
    :effect (and (not (holding ?b)) (handempty) (at ?b ?s) (not (free ?s))))
  (:action unstack
    :parameters (?b - block ?c - block)
    :precondition (and (on ?b ?c) (clear ?b) (handempty))
    :effect (and (not (on ?b ?c)) (clear ?c) (not (handempty)) (holding ?b)))
  (:action stack
    :parameters (?b - block ?c - block)
    :precondition (and (holding ?b) (clear ?c) (not (= ?b ?c)))
    :effect (and (not (holding ?b)) (handempty) (on ?b ?c) (not (clear ?c)))))
