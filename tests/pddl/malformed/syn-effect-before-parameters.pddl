(define (domain d)
  (:predicates (p ?x))
  (:action a
    :effect (p ?x)
    :parameters (?x)))
