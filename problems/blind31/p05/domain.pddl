; blind31 p05: set a place (a plate with a cup on it, a fork, a knife) from
; a cluttered counter. Typed with a subtype (plate), negative preconditions
; ((topped ?p)), :equality, an existential goal (either plate will do).
(define (domain b31-setting)
  (:requirements :strips :typing :negative-preconditions :equality
                 :existential-preconditions)
  (:types plate - thing
          thing zone)
  (:predicates (at ?t - thing ?z - zone) (on ?t - thing ?p - plate)
               (holding ?t - thing) (handempty) (topped ?p - plate))
  (:action pick
    :parameters (?t - thing ?z - zone)
    :precondition (and (at ?t ?z) (handempty) (not (topped ?t)))
    :effect (and (not (at ?t ?z)) (holding ?t) (not (handempty))))
  (:action unstack
    :parameters (?t - thing ?p - plate)
    :precondition (and (on ?t ?p) (handempty) (not (topped ?t)))
    :effect (and (not (on ?t ?p)) (not (topped ?p)) (holding ?t) (not (handempty))))
  (:action place
    :parameters (?t - thing ?z - zone)
    :precondition (holding ?t)
    :effect (and (at ?t ?z) (handempty) (not (holding ?t))))
  (:action stack
    :parameters (?t - thing ?p - plate)
    :precondition (and (holding ?t) (not (topped ?p)) (not (= ?t ?p)))
    :effect (and (on ?t ?p) (topped ?p) (handempty) (not (holding ?t)))))
