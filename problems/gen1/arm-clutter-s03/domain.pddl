; gen1 arm-clutter: arm-pick-place's pick and place (docs: domains/arm-pick-place),
; without stack/unstack: the generated clutter is never stacked.
(define (domain gen1-arm-clutter)
  (:requirements :strips :typing)
  (:types block region)
  (:predicates (at ?b - block ?r - region)
               (holding ?b - block)
               (handempty))

  (:action pick
    :parameters (?b - block ?from - region)
    :precondition (and (at ?b ?from) (handempty))
    :effect (and (not (at ?b ?from)) (not (handempty)) (holding ?b)))

  (:action place
    :parameters (?b - block ?to - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (at ?b ?to))))
