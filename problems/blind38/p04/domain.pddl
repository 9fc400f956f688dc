; blind38 p04: a planar disk that lifts light things and only shoves heavy ones.
(define (domain shove-lift)
  (:requirements :strips :typing :action-costs)
  (:types obj zone)
  (:predicates (in ?o - obj ?z - zone) (liftable ?o - obj) (held ?o - obj) (free))
  (:functions (total-cost) - number)
  (:action lift
    :parameters (?o - obj ?z - zone)
    :precondition (and (in ?o ?z) (liftable ?o) (free))
    :effect (and (held ?o) (not (in ?o ?z)) (not (free)) (increase (total-cost) 1)))
  (:action drop
    :parameters (?o - obj ?z - zone)
    :precondition (held ?o)
    :effect (and (in ?o ?z) (free) (not (held ?o)) (increase (total-cost) 1)))
  (:action shove
    :parameters (?o - obj ?from - zone ?to - zone)
    :precondition (and (in ?o ?from) (free))
    :effect (and (in ?o ?to) (not (in ?o ?from)) (increase (total-cost) 2))))
