(define (domain d)
  (:requirements :typing)
  (:types block place)
  (:constants table - place)
  (:predicates (clear ?b - block))
  (:action a
    :parameters ()
    :effect (clear table)))
