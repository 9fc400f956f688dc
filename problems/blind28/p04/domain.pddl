; Singulation: parts may be picked and placed, a crate may only be pushed
; (it is too wide for the gripper, and not liftable). A push is slower than
; a pick or a place (cost 2). Typed hierarchy, static capability facts,
; equality under not.
(define (domain b28-singulate)
  (:requirements :strips :typing :equality :action-costs)
  (:types part crate - item item zone)
  (:predicates (at ?i - item ?z - zone) (holding ?p - part) (hand-free)
               (liftable ?i - item) (pushable ?i - item))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?i - item ?from ?to - zone)
    :precondition (and (at ?i ?from) (pushable ?i) (hand-free)
                       (not (= ?from ?to)))
    :effect (and (not (at ?i ?from)) (at ?i ?to) (increase (total-cost) 2)))

  (:action pick
    :parameters (?p - part ?z - zone)
    :precondition (and (at ?p ?z) (liftable ?p) (hand-free))
    :effect (and (not (at ?p ?z)) (holding ?p) (not (hand-free))
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?p - part ?z - zone)
    :precondition (holding ?p)
    :effect (and (at ?p ?z) (not (holding ?p)) (hand-free)
                 (increase (total-cost) 1))))
