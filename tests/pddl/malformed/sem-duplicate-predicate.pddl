(define (domain d)
  (:predicates (p ?x)
               (q)
               (p ?y ?z)))
