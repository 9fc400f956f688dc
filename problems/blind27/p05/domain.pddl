; Planar disk, carries only; the goal is a forall over the pieces.
(define (domain b27-pack)
  (:requirements :strips :typing :universal-preconditions)
  (:types piece area)
  (:predicates (at ?o - piece ?a - area) (holding ?o - piece) (handempty))
  (:action grab
    :parameters (?o - piece ?a - area)
    :precondition (and (at ?o ?a) (handempty))
    :effect (and (not (at ?o ?a)) (not (handempty)) (holding ?o)))
  (:action release
    :parameters (?o - piece ?a - area)
    :precondition (holding ?o)
    :effect (and (at ?o ?a) (handempty) (not (holding ?o)))))
