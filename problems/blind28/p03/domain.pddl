; PDDLStream's pr2 "pour" in miniature: the cup is held over the bowl (a
; move whose tool ends over the bowl, a movable body) before it is poured;
; the bowl may only be poured into on the mat or the trivet. Untyped, static
; type predicates, constants, disjunctive preconditions, equality.
(define (domain b28-pour)
  (:requirements :strips :negative-preconditions :disjunctive-preconditions
                 :equality)
  (:constants mat trivet)
  (:predicates (at ?o ?s) (holding ?o) (handempty) (cup ?o) (bowl ?o)
               (spot ?s) (over ?c ?b) (has-water ?c) (full ?b))

  (:action pick
    :parameters (?o ?s)
    :precondition (and (at ?o ?s) (handempty) (or (cup ?o) (bowl ?o)))
    :effect (and (not (at ?o ?s)) (holding ?o) (not (handempty))))

  (:action place
    :parameters (?o ?s)
    :precondition (and (holding ?o) (spot ?s))
    :effect (and (at ?o ?s) (handempty) (not (holding ?o))))

  (:action hold-over
    :parameters (?c ?b)
    :precondition (and (holding ?c) (cup ?c) (bowl ?b) (not (= ?c ?b)))
    :effect (over ?c ?b))

  (:action pour
    :parameters (?c ?b)
    :precondition (and (holding ?c) (over ?c ?b) (has-water ?c)
                       (or (at ?b mat) (at ?b trivet)))
    :effect (and (full ?b) (not (has-water ?c)))))
