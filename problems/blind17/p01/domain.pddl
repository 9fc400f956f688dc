; blind17 p01: typed pick / place between two levels (KUKA iiwa).
; Spots are typed by the level they lie on (low: the bench, high: the
; counter); items are cubes or cans. Actions take `either` types.
(define (domain two-levels)
  (:requirements :strips :typing)
  (:types cube can - item
          low high - spot
          item spot)
  (:predicates (at ?o - item ?s - spot)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - (either cube can) ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?s - (either low high))
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?s))))
