(define (domain d)
  (:requirements :action-costs)
  (:predicates (p))
  (:functions (total-cost) (fuel-used))
  (:action a
    :parameters ()
    :effect (and (p) (increase (fuel-used) 1))))
