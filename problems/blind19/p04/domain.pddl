; blind19 p04: typed pick / place for the planar disk, one object per
; region. Nothing here says that a puck stands in the only doorway, nor
; which suction face lets the bar through it.
(define (domain doorway)
  (:requirements :strips :typing)
  (:types thing spot)
  (:predicates (at ?o - thing ?s - spot)
               (free ?s - spot)
               (holding ?o - thing)
               (handempty))

  (:action pick
    :parameters (?o - thing ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (free ?s)
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - thing ?s - spot)
    :precondition (and (holding ?o) (free ?s))
    :effect (and (at ?o ?s) (not (free ?s))
                 (not (holding ?o)) (handempty))))
