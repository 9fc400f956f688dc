; blind22 p03: typed, push only (the puck is never lifted: the domain has no
; pick), with :equality (no push into the zone the puck is in) and
; :action-costs: a push costs `(push-cost ?from ?to)`, its rough length.
(define (domain post-gap)
  (:requirements :strips :typing :equality :action-costs)
  (:types puck zone)
  (:predicates (at ?p - puck ?z - zone))
  (:functions (total-cost) - number
              (push-cost ?from - zone ?to - zone) - number)

  (:action push
    :parameters (?p - puck ?from - zone ?to - zone)
    :precondition (and (at ?p ?from) (not (= ?from ?to)))
    :effect (and (not (at ?p ?from)) (at ?p ?to)
                 (increase (total-cost) (push-cost ?from ?to)))))
