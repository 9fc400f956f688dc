; A Panda moves objects between regions. The symbolic level knows only which
; region an object is in: nothing about grasps, roofs or reach, which are
; left to the geometry.
(define (domain blind2-nook)
  (:requirements :strips :typing)
  (:types obj region)
  (:predicates (in ?o - obj ?r - region)
               (holding ?o - obj)
               (handempty))

  (:action pick
    :parameters (?o - obj ?r - region)
    :precondition (and (in ?o ?r) (handempty))
    :effect (and (not (in ?o ?r)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - obj ?r - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (in ?o ?r))))
