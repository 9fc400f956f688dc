; blind16 p03: typed pick / place (Panda); several items may share a
; region. Unit costs.
(define (domain panda-pack)
  (:requirements :strips :typing :universal-preconditions)
  (:types item area)
  (:predicates (at ?o - item ?a - area)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - item ?a - area)
    :precondition (and (at ?o ?a) (handempty))
    :effect (and (not (at ?o ?a)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?a - area)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?a))))
