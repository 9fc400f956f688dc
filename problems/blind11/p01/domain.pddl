;; blind11 p01: things are lifted out of a container or off the bench
;; and set down on a pad. One thing held at a time.
(define (domain blind11-liftout)
  (:requirements :strips :typing)
  (:types thing spot)
  (:predicates (resting ?t - thing ?s - spot)
               (gripping ?t - thing)
               (hand-idle))
  (:action lift-out
    :parameters (?t - thing ?s - spot)
    :precondition (and (resting ?t ?s) (hand-idle))
    :effect (and (not (resting ?t ?s)) (not (hand-idle)) (gripping ?t)))
  (:action set-down
    :parameters (?t - thing ?s - spot)
    :precondition (gripping ?t)
    :effect (and (not (gripping ?t)) (hand-idle) (resting ?t ?s))))
