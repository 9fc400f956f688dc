(define (domain d)
  (:requirements :typing)
  (:types truck - vehicle place)
  (:predicates (at ?t - truck ?p - place)))
