; A Panda moves objects between regions and stacks them. The symbolic level
; says where each object is, (in ?o ?r) for a region, (on ?o ?p) for another
; object, and nothing else: no clear, so what rests on an object does not
; stop it from being picked.
(define (domain blind2-stack)
  (:requirements :strips :typing :equality)
  (:types obj region)
  (:predicates (in ?o - obj ?r - region)
               (on ?o - obj ?p - obj)
               (holding ?o - obj)
               (handempty))

  (:action pick
    :parameters (?o - obj ?r - region)
    :precondition (and (in ?o ?r) (handempty))
    :effect (and (not (in ?o ?r)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - obj ?r - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (in ?o ?r)))

  (:action unstack
    :parameters (?o - obj ?p - obj)
    :precondition (and (on ?o ?p) (handempty))
    :effect (and (not (on ?o ?p)) (not (handempty)) (holding ?o)))

  (:action stack
    :parameters (?o - obj ?p - obj)
    :precondition (and (holding ?o) (not (= ?o ?p)))
    :effect (and (not (holding ?o)) (handempty) (on ?o ?p))))
