(define (domain d)
  (:predicates (p ?x) (q))
  (:action a
    :parameters (?x)
    :effect (and (p ?x)
                 (or (q)))))
