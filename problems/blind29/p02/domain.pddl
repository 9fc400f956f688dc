; blind29 p02: a KUKA iiwa mounted on a wall, its first axis horizontal,
; rearranging a bench below it. Untyped STRIPS with static type predicates;
; the problem's goal is disjunctive.
(define (domain b29-wallarm)
  (:requirements :strips :disjunctive-preconditions)
  (:predicates (item ?o) (spot ?s) (at ?o ?s) (holding ?o) (hand-empty))

  (:action pick
    :parameters (?o ?s)
    :precondition (and (item ?o) (spot ?s) (at ?o ?s) (hand-empty))
    :effect (and (not (at ?o ?s)) (holding ?o) (not (hand-empty))))

  (:action place
    :parameters (?o ?s)
    :precondition (and (item ?o) (spot ?s) (holding ?o))
    :effect (and (at ?o ?s) (hand-empty) (not (holding ?o)))))
