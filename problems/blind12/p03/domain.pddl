;; blind12 p03: cartons are taken off the counter and shelved; with
;; action costs (taking 1, shelving 2).
(define (domain blind12-shelving)
  (:requirements :strips :typing :action-costs)
  (:types carton place)
  (:predicates (stands ?c - carton ?p - place)
               (carrying ?c - carton)
               (gripper-empty))
  (:functions (total-cost) - number)
  (:action take
    :parameters (?c - carton ?p - place)
    :precondition (and (stands ?c ?p) (gripper-empty))
    :effect (and (carrying ?c) (not (stands ?c ?p)) (not (gripper-empty))
                 (increase (total-cost) 1)))
  (:action shelve
    :parameters (?c - carton ?p - place)
    :precondition (carrying ?c)
    :effect (and (stands ?c ?p) (gripper-empty) (not (carrying ?c))
                 (increase (total-cost) 2))))
