; Pick, place and stack: things go into regions or onto each other. Whether
; a thing stands on another, and whether the arm can get there, is left to
; the geometry.
(define (domain blind5-tower)
  (:requirements :strips :typing)
  (:types block region)
  (:predicates (in ?b - block ?r - region)
               (on ?b - block ?c - block)
               (clear ?b - block)
               (holding ?b - block)
               (free))
  (:action pick
    :parameters (?b - block ?r - region)
    :precondition (and (in ?b ?r) (clear ?b) (free))
    :effect (and (not (in ?b ?r)) (not (clear ?b)) (not (free)) (holding ?b)))
  (:action place
    :parameters (?b - block ?r - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (free) (clear ?b) (in ?b ?r)))
  (:action unstack
    :parameters (?b - block ?c - block)
    :precondition (and (on ?b ?c) (clear ?b) (free))
    :effect (and (not (on ?b ?c)) (not (clear ?b)) (not (free)) (holding ?b) (clear ?c)))
  (:action stack
    :parameters (?b - block ?c - block)
    :precondition (and (holding ?b) (clear ?c))
    :effect (and (not (holding ?b)) (not (clear ?c)) (free) (clear ?b) (on ?b ?c))))
