; blind14 p01: sort cubes by colour into two bins (KUKA iiwa).
; Typed, colours as domain constants, the goal a forall over imply.
(define (domain kuka-sort)
  (:requirements :strips :typing :universal-preconditions
                 :disjunctive-preconditions)
  (:types cube area colour)
  (:constants red blue - colour)
  (:predicates (in ?c - cube ?a - area)
               (holding ?c - cube)
               (free)
               (colour-of ?c - cube ?k - colour))

  (:action pick
    :parameters (?c - cube ?a - area)
    :precondition (and (in ?c ?a) (free))
    :effect (and (holding ?c) (not (in ?c ?a)) (not (free))))

  (:action drop
    :parameters (?c - cube ?a - area)
    :precondition (holding ?c)
    :effect (and (in ?c ?a) (free) (not (holding ?c)))))
