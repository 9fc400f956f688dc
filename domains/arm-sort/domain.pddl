; Sorting with a Franka Panda: cubes go from the workspace into the bin of
; their colour, among fixed clutter. Symbolically trivial (each cube is one
; pick and one place); the work is geometric: reaching between obstacles
; and into trays with rims.
(define (domain arm-sort)
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
