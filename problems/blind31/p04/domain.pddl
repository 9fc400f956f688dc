; blind31 p04: deliver three target pucks, one per goal zone, through a
; field of distractors. Typed with subtypes, :action-costs (constant),
; a negative precondition (a goal takes one puck), a forall/exists goal.
(define (domain b31-pucks)
  (:requirements :strips :typing :negative-preconditions :action-costs
                 :universal-preconditions :existential-preconditions)
  (:types puck crate - item
          target - puck
          area goal - zone
          item zone)
  (:predicates (at ?o - item ?z - zone) (holding ?o - item) (handempty)
               (full ?z - zone))
  (:functions (total-cost) - number)
  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (not (at ?o ?z)) (not (full ?z)) (holding ?o) (not (handempty))
                 (increase (total-cost) 1)))
  ; set anything down in an ordinary area (parking costs more)
  (:action place
    :parameters (?o - item ?z - area)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (handempty) (not (holding ?o))
                 (increase (total-cost) 2)))
  ; a target puck into a goal zone that holds nothing yet
  (:action deliver
    :parameters (?t - target ?g - goal)
    :precondition (and (holding ?t) (not (full ?g)))
    :effect (and (at ?t ?g) (full ?g) (handempty) (not (holding ?t))
                 (increase (total-cost) 1))))
