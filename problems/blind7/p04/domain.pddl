;; Sorting trays: a tool is lifted out of one tray and laid into another.
(define (domain blind7-trays)
  (:requirements :typing :negative-preconditions)
  (:types thing place - object
          tool - thing
          tray - place)
  (:predicates (resting ?t - thing ?p - place)
               (gripped ?t - thing)
               (hand-busy))
  (:action lift-out
    :parameters (?t - thing ?p - place)
    :precondition (and (resting ?t ?p) (not (hand-busy)))
    :effect (and (not (resting ?t ?p)) (gripped ?t) (hand-busy)))
  (:action lay-in
    :parameters (?t - thing ?p - place)
    :precondition (gripped ?t)
    :effect (and (not (gripped ?t)) (not (hand-busy)) (resting ?t ?p))))
