; blind23 p04: untyped STRIPS with type predicates and :equality: pick and
; place between spots, for a Panda turned 90 degrees and set off the
; origin. Unit costs.
(define (domain between-blocks)
  (:requirements :strips :equality)
  (:predicates (block ?b) (spot ?s)
               (at ?b ?s) (holding ?b) (free))

  (:action pick
    :parameters (?b ?s)
    :precondition (and (block ?b) (spot ?s) (at ?b ?s) (free))
    :effect (and (not (at ?b ?s)) (not (free)) (holding ?b)))

  (:action place
    :parameters (?b ?s)
    :precondition (and (block ?b) (spot ?s) (holding ?b))
    :effect (and (not (holding ?b)) (free) (at ?b ?s))))
