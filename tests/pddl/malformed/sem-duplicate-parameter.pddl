(define (domain d)
  (:predicates (on ?x ?y))
  (:action a
    :parameters (?x ?y ?x)
    :effect (on ?x ?y)))
