; blind18 p04: typed pick / place for the planar disk, with a type
; hierarchy for places and a (free ?p) occupancy fact. Nothing here says
; that the corridor is a dead end: which crate blocks which is geometry's.
(define (domain corridor)
  (:requirements :strips :typing)
  (:types bay park - place
          place crate)
  (:predicates (at ?c - crate ?p - place)
               (free ?p - place)
               (holding ?c - crate)
               (handempty))

  (:action pick
    :parameters (?c - crate ?p - place)
    :precondition (and (at ?c ?p) (handempty))
    :effect (and (not (at ?c ?p)) (free ?p)
                 (not (handempty)) (holding ?c)))

  (:action place
    :parameters (?c - crate ?p - place)
    :precondition (and (holding ?c) (free ?p))
    :effect (and (at ?c ?p) (not (free ?p))
                 (not (holding ?c)) (handempty))))
