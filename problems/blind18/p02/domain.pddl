; blind18 p02: typed pick / place with occupancy written as a negative
; precondition, (not (occupied ?s)).
(define (domain grid-rearrange)
  (:requirements :strips :typing :negative-preconditions)
  (:types cube slot)
  (:predicates (in ?c - cube ?s - slot)
               (occupied ?s - slot)
               (holding ?c - cube)
               (handempty))

  (:action pick
    :parameters (?c - cube ?s - slot)
    :precondition (and (in ?c ?s) (handempty))
    :effect (and (not (in ?c ?s)) (not (occupied ?s))
                 (not (handempty)) (holding ?c)))

  (:action place
    :parameters (?c - cube ?s - slot)
    :precondition (and (holding ?c) (not (occupied ?s)))
    :effect (and (in ?c ?s) (occupied ?s)
                 (not (holding ?c)) (handempty))))
