(define (domain d)
  (:predicates (on ?x ?y))
  (:action a
    :parameters (?x ?y)
    :precondition (on ?x)
    :effect (on ?y ?x)))
