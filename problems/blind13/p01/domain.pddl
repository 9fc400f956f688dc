; blind13 p01: untyped STRIPS, static type predicates, own action names.
(define (domain kuka-trough)
  (:requirements :strips)
  (:predicates (item ?x) (spot ?s) (at ?x ?s) (holding ?x) (free-hand))

  (:action grab
    :parameters (?x ?s)
    :precondition (and (item ?x) (spot ?s) (at ?x ?s) (free-hand))
    :effect (and (holding ?x) (not (at ?x ?s)) (not (free-hand))))

  (:action drop
    :parameters (?x ?s)
    :precondition (and (item ?x) (spot ?s) (holding ?x))
    :effect (and (at ?x ?s) (free-hand) (not (holding ?x)))))
