(define (domain d)
  (:requirements :fluents)
  (:predicates (p))
  (:functions (total-cost) (fuel))
  (:action a :parameters ()
    :effect (and (p) (increase (total-cost) (fuel))))
  ; refueling makes (fuel) a fluent, so it is no longer a static action cost
  (:action refuel :parameters ()
    :effect (increase (fuel) 5)))
