; A robot carries things between regions. The symbolic level records only
; which region a thing is in: whether it fits there, whether something is in
; the way, and how it is held are left to the geometry.
(define (domain blind5-carry)
  (:requirements :strips :typing)
  (:types thing region)
  (:predicates (in ?t - thing ?r - region)
               (holding ?t - thing)
               (free))
  (:action pick
    :parameters (?t - thing ?r - region)
    :precondition (and (in ?t ?r) (free))
    :effect (and (not (in ?t ?r)) (not (free)) (holding ?t)))
  (:action place
    :parameters (?t - thing ?r - region)
    :precondition (holding ?t)
    :effect (and (not (holding ?t)) (free) (in ?t ?r))))
