; blind29 p01: exchange two items through a window (a pass-through hatch)
; in the wall of a booth. Typed, action costs: handling inside the booth
; (reaching through the window) costs 3, outside 1 (a function of the zone).
(define (domain b29-hatch)
  (:requirements :strips :typing :action-costs)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone) (holding ?o - item) (hand-empty))
  (:functions (total-cost) - number
              (handling ?z - zone) - number)

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (hand-empty))
    :effect (and (not (at ?o ?z)) (holding ?o) (not (hand-empty))
                 (increase (total-cost) (handling ?z))))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (hand-empty) (not (holding ?o))
                 (increase (total-cost) (handling ?z)))))
