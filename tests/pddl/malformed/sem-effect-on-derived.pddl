(define (domain d)
  (:requirements :derived-predicates)
  (:predicates (on ?x ?y) (above ?x ?y))
  (:derived (above ?x ?y) (on ?x ?y))
  (:action a
    :parameters (?x ?y)
    :effect (above ?x ?y)))
