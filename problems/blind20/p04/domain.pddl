; blind20 p04: typed pick / place for the planar disk, one object per
; spot (negative precondition on `occupied`). Nothing says which suction
; face lets the bar round the corner of the L-shaped corridor.
(define (domain l-corridor)
  (:requirements :strips :typing :negative-preconditions)
  (:types thing spot)
  (:predicates (at ?o - thing ?s - spot)
               (occupied ?s - spot)
               (holding ?o - thing)
               (handempty))

  (:action pick
    :parameters (?o - thing ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (occupied ?s))
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - thing ?s - spot)
    :precondition (and (holding ?o) (not (occupied ?s)))
    :effect (and (at ?o ?s) (occupied ?s)
                 (not (holding ?o)) (handempty))))
