; A disk robot pushes a box into a region (render tests).
(define (domain render-planar)
  (:requirements :strips :typing)
  (:types item region)
  (:predicates (at ?o - item ?r - region))
  (:action push
    :parameters (?o - item ?from - region ?to - region)
    :precondition (at ?o ?from)
    :effect (and (not (at ?o ?from)) (at ?o ?to))))
