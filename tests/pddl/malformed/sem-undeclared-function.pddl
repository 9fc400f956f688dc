(define (domain d)
  (:requirements :action-costs)
  (:predicates (road ?a ?b))
  (:functions (total-cost))
  (:action drive
    :parameters (?a ?b)
    :precondition (road ?a ?b)
    :effect (increase (total-cost) (distance ?a ?b))))
