; A robot slides a heavy thing over its support from region to region. It
; cannot lift it (there is no pick); whether a push is possible (friction
; cone, walls, room for the pusher) is left to the geometry.
(define (domain blind4-slide)
  (:requirements :strips :typing)
  (:types heavy region)
  (:predicates (in ?h - heavy ?r - region))
  (:action push
    :parameters (?h - heavy ?from - region ?to - region)
    :precondition (in ?h ?from)
    :effect (and (not (in ?h ?from)) (in ?h ?to))))
