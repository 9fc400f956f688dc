;; Shelving: a carton goes from one shelf level to another. The arm is
;; "busy" while it holds something; nothing says how (a negative
;; precondition instead of a hand-empty fact). Taking off a shelf costs
;; more than putting on one.
(define (domain blind7-shelving)
  (:requirements :typing :negative-preconditions :action-costs)
  (:types goods level - object
          carton - goods
          board - level)
  (:predicates (sits ?g - goods ?l - level)
               (carries ?g - goods)
               (busy))
  (:functions (total-cost) - number)
  (:action take-off
    :parameters (?g - goods ?from - level)
    :precondition (and (sits ?g ?from) (not (busy)))
    :effect (and (not (sits ?g ?from)) (carries ?g) (busy)
                 (increase (total-cost) 4)))
  (:action shelve
    :parameters (?g - goods ?onto - level)
    :precondition (and (carries ?g))
    :effect (and (not (carries ?g)) (not (busy)) (sits ?g ?onto)
                 (increase (total-cost) 2))))
