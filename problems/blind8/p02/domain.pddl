;; Kitting: parts go into zones one at a time. A zone's capacity is not
;; symbolic: whether a part fits is the geometry's to decide.
(define (domain blind8-kitting)
  (:requirements :strips :typing)
  (:types thing zone)
  (:predicates (in ?t - thing ?z - zone)
               (carrying ?t - thing)
               (free-gripper))
  (:action grab
    :parameters (?t - thing ?z - zone)
    :precondition (and (in ?t ?z) (free-gripper))
    :effect (and (not (in ?t ?z)) (not (free-gripper)) (carrying ?t)))
  (:action drop
    :parameters (?t - thing ?z - zone)
    :precondition (carrying ?t)
    :effect (and (not (carrying ?t)) (free-gripper) (in ?t ?z))))
