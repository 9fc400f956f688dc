; blind37 p02: task A, typed, no occupancy (no clear), other names, action costs.
(define (domain tower-typed)
  (:requirements :strips :typing :action-costs)
  (:types part area - thing thing)
  (:predicates (resting ?p - part ?t - thing)
               (in-gripper ?p - part)
               (gripper-free))
  (:functions (total-cost) - number)
  (:action grab
    :parameters (?p - part ?t - thing)
    :precondition (and (resting ?p ?t) (gripper-free))
    :effect (and (in-gripper ?p) (not (resting ?p ?t)) (not (gripper-free))
                 (increase (total-cost) 1)))
  (:action set-down
    :parameters (?p - part ?a - area)
    :precondition (in-gripper ?p)
    :effect (and (resting ?p ?a) (gripper-free) (not (in-gripper ?p))
                 (increase (total-cost) 1)))
  (:action set-on
    :parameters (?p - part ?q - part)
    :precondition (in-gripper ?p)
    :effect (and (resting ?p ?q) (gripper-free) (not (in-gripper ?p))
                 (increase (total-cost) 2))))
