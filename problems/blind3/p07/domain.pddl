; A robot moves objects between regions. The symbolic level knows only which
; region an object is in: no clear, no capacity. Whether an object fits a
; region, and whether another must leave first, are facts of geometry.
(define (domain blind3-pick-place)
  (:requirements :strips :typing)
  (:types obj region)
  (:predicates (at ?o - obj ?r - region)
               (holding ?o - obj)
               (handempty))
  (:action pick
    :parameters (?o - obj ?r - region)
    :precondition (and (at ?o ?r) (handempty))
    :effect (and (not (at ?o ?r)) (not (handempty)) (holding ?o)))
  (:action place
    :parameters (?o - obj ?r - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?r))))
