(define (domain d)
  (:requirements :typing)
  (:types block)
  (:predicates (clear ?x - block))
  (:action a
    :parameters (?x - blok)
    :effect (clear ?x)))
