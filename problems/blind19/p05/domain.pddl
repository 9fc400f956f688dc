; blind19 p05: kitting. Typed with a type hierarchy for items (cube, can,
; bar under item) and one object per region. The goal names each item's
; pocket; the order of the twelve actions is free.
(define (domain kitting)
  (:requirements :strips :typing)
  (:types cube can bar - item
          item spot)
  (:predicates (at ?o - item ?s - spot)
               (free ?s - spot)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (free ?s)
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?s - spot)
    :precondition (and (holding ?o) (free ?s))
    :effect (and (at ?o ?s) (not (free ?s))
                 (not (holding ?o)) (handempty))))
