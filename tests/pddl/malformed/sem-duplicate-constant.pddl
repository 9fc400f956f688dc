(define (domain d)
  (:requirements :typing)
  (:types place)
  (:constants home work - place
              home - place)
  (:predicates (at ?p - place)))
