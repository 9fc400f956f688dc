; blind13 p03: typed, with action costs (lifting costs 1, setting down 2).
(define (domain xarm-slot)
  (:requirements :strips :typing :action-costs)
  (:types can zone)
  (:predicates (stands ?c - can ?z - zone)
               (in-hand ?c - can)
               (gripper-free))
  (:functions (total-cost) - number)

  (:action lift
    :parameters (?c - can ?z - zone)
    :precondition (and (stands ?c ?z) (gripper-free))
    :effect (and (in-hand ?c) (not (stands ?c ?z)) (not (gripper-free))
                 (increase (total-cost) 1)))

  (:action set-down
    :parameters (?c - can ?z - zone)
    :precondition (in-hand ?c)
    :effect (and (stands ?c ?z) (gripper-free) (not (in-hand ?c))
                 (increase (total-cost) 2))))
