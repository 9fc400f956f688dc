; blind31 p03: unpack a crate: the two parts needed lie under other things.
; Untyped STRIPS with static type predicates, explicit (clear ?x) facts,
; :equality, a negative and disjunctive precondition (only kit parts go
; into the kit), a disjunctive goal.
(define (domain b31-crate)
  (:requirements :strips :equality :negative-preconditions :disjunctive-preconditions)
  (:predicates (item ?x) (spot ?s) (kit ?s) (kit-part ?x)
               (at ?x ?s) (on ?x ?y) (clear ?x) (holding ?x) (handempty))
  (:action pick
    :parameters (?x ?s)
    :precondition (and (item ?x) (spot ?s) (at ?x ?s) (clear ?x) (handempty))
    :effect (and (not (at ?x ?s)) (holding ?x) (not (handempty))))
  (:action unstack
    :parameters (?x ?y)
    :precondition (and (item ?x) (item ?y) (on ?x ?y) (clear ?x) (handempty))
    :effect (and (not (on ?x ?y)) (clear ?y) (holding ?x) (not (handempty))))
  (:action place
    :parameters (?x ?s)
    :precondition (and (holding ?x) (spot ?s) (or (not (kit ?s)) (kit-part ?x)))
    :effect (and (at ?x ?s) (handempty) (not (holding ?x))))
  (:action stack
    :parameters (?x ?y)
    :precondition (and (holding ?x) (item ?y) (clear ?y) (not (= ?x ?y)))
    :effect (and (on ?x ?y) (not (clear ?y)) (handempty) (not (holding ?x)))))
