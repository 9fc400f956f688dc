; Kitchen with a batch oven: one bake cooks every dish standing in the oven
; (a forall/when effect). Baking is dear (cost 5: preheating), so two dishes
; baked together (13) beat two bakes (18), if both fit in the oven at once.
(define (domain b28-oven)
  (:requirements :strips :typing :negative-preconditions
                 :conditional-effects :action-costs)
  (:types dish spot)
  (:predicates (at ?d - dish ?s - spot) (holding ?d - dish) (busy)
               (cooked ?d - dish) (oven ?s - spot))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?d - dish ?s - spot)
    :precondition (and (at ?d ?s) (not (busy)))
    :effect (and (not (at ?d ?s)) (holding ?d) (busy)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?d - dish ?s - spot)
    :precondition (holding ?d)
    :effect (and (at ?d ?s) (not (holding ?d)) (not (busy))
                 (increase (total-cost) 1)))

  (:action bake
    :parameters (?o - spot)
    :precondition (and (oven ?o) (not (busy)))
    :effect (and (forall (?d - dish) (when (at ?d ?o) (cooked ?d)))
                 (increase (total-cost) 5))))
