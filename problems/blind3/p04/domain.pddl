; A planar disk pushes a crate over a bench from region to region. It cannot
; lift the crate (there is no pick). Any region may follow any other
; symbolically; whether a push between them is possible (the friction cone,
; walls in the way) is left to the geometry.
(define (domain blind3-push)
  (:requirements :strips :typing)
  (:types item region)
  (:predicates (at ?o - item ?r - region))
  (:action push
    :parameters (?o - item ?from - region ?to - region)
    :precondition (at ?o ?from)
    :effect (and (not (at ?o ?from)) (at ?o ?to))))
