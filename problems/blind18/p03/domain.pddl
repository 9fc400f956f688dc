; blind18 p03: typed textbook pick / place; (holding ?o) does not say where
; the object came from, so a regrasp passes "holding" twice.
(define (domain regrasp)
  (:requirements :strips :typing)
  (:types part zone)
  (:predicates (at ?o - part ?z - zone)
               (holding ?o - part)
               (handempty))

  (:action pick
    :parameters (?o - part ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (not (at ?o ?z)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - part ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (not (holding ?o)) (handempty))))
