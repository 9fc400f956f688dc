(define (domain d)
  (:requirements :typing)
  (:types a - b
          b - a)
  (:predicates (p ?x - a)))
