(define (domain d)
  (:predicates (p ?x))
  (:action :parameters (?x) :effect (p ?x)))
