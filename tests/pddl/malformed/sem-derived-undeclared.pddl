(define (domain d)
  (:requirements :derived-predicates)
  (:predicates (on ?x ?y))
  (:derived (above ?x ?y) (on ?x ?y)))
