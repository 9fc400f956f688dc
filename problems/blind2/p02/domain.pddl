; A Panda moves objects between regions, and the domain says only where an
; object is: (on ?o ?r). No clear, no capacity: whether a region has room for
; another object is a fact of geometry.
(define (domain blind2-on)
  (:requirements :strips :typing)
  (:types obj region)
  (:predicates (on ?o - obj ?r - region)
               (holding ?o - obj)
               (handempty))

  (:action pick
    :parameters (?o - obj ?r - region)
    :precondition (and (on ?o ?r) (handempty))
    :effect (and (not (on ?o ?r)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - obj ?r - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (on ?o ?r))))
