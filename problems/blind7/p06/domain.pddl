;; Stowing with an inspection on the way: an item is grasped, inspected
;; while held (symbolic only), and stowed in a bay.
(define (domain blind7-stow)
  (:requirements :typing :negative-preconditions :action-costs)
  (:types item bay - object
          spool - item)
  (:predicates (stowed ?i - item ?b - bay)
               (grasped ?i - item)
               (inspected ?i - item)
               (hand-idle))
  (:functions (total-cost) - number)
  (:action grasp-item
    :parameters (?i - item ?b - bay)
    :precondition (and (stowed ?i ?b) (hand-idle))
    :effect (and (not (stowed ?i ?b)) (not (hand-idle)) (grasped ?i)
                 (increase (total-cost) 2)))
  (:action inspect
    :parameters (?i - item)
    :precondition (and (grasped ?i) (not (inspected ?i)))
    :effect (and (inspected ?i) (increase (total-cost) 1)))
  (:action stow
    :parameters (?i - item ?b - bay)
    :precondition (and (grasped ?i) (inspected ?i))
    :effect (and (not (grasped ?i)) (hand-idle) (stowed ?i ?b)
                 (increase (total-cost) 2))))
