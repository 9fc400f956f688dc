(define (domain d)
  (:requirements :action-costs)
  (:predicates (p))
  (:functions (total-cost))
  (:action a
    :parameters ()
    :effect (and (p) (increase (total-cost) (total-cost)))))
