; blind15 p07: untyped planar carry with an existential goal.
(define (domain planar-maze)
  (:requirements :strips :existential-preconditions)
  (:predicates (puck ?o) (spot ?s) (dock ?s) (at ?o ?s) (carrying ?o) (idle))

  (:action grab
    :parameters (?o ?s)
    :precondition (and (puck ?o) (spot ?s) (at ?o ?s) (idle))
    :effect (and (carrying ?o) (not (at ?o ?s)) (not (idle))))

  (:action drop
    :parameters (?o ?s)
    :precondition (and (puck ?o) (spot ?s) (carrying ?o))
    :effect (and (at ?o ?s) (idle) (not (carrying ?o)))))
