; blind37 p06: task B with a `move` through the doorway (the robot's side of the wall is
; symbolic), negative preconditions, derived predicates and a forall goal.
(define (domain bay-move)
  (:requirements :strips :typing :negative-preconditions :derived-predicates
                 :existential-preconditions :universal-preconditions)
  (:types crate area - object
          doorway - area)
  (:predicates (in ?c - crate ?a - area)
               (carrying ?c - crate)
               (loaded)
               (in-east)
               (west-area ?a - area) (east-area ?a - area)
               (delivered ?c - crate))
  (:derived (loaded) (exists (?c - crate) (carrying ?c)))
  (:derived (delivered ?c - crate) (exists (?a - area) (and (east-area ?a) (in ?c ?a))))
  (:action grab
    :parameters (?c - crate ?a - area)
    :precondition (and (in ?c ?a) (west-area ?a) (not (in-east)) (not (loaded)))
    :effect (and (carrying ?c) (not (in ?c ?a))))
  (:action drop
    :parameters (?c - crate ?a - area)
    :precondition (and (carrying ?c) (east-area ?a) (in-east))
    :effect (and (in ?c ?a) (not (carrying ?c))))
  (:action go-east
    :parameters (?d - doorway)
    :precondition (not (in-east))
    :effect (in-east))
  (:action go-west
    :parameters (?d - doorway)
    :precondition (in-east)
    :effect (not (in-east))))
