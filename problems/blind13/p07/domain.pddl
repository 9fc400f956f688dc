; blind13 p07: untyped, fetch / shelve, the hand state as a predicate.
(define (domain panda-shelf)
  (:requirements :strips)
  (:predicates (thing ?o) (surface ?s) (on-surface ?o ?s) (in-gripper ?o) (gripper-empty))

  (:action fetch
    :parameters (?o ?s)
    :precondition (and (thing ?o) (surface ?s) (on-surface ?o ?s) (gripper-empty))
    :effect (and (in-gripper ?o) (not (on-surface ?o ?s)) (not (gripper-empty))))

  (:action shelve
    :parameters (?o ?s)
    :precondition (and (thing ?o) (surface ?s) (in-gripper ?o))
    :effect (and (on-surface ?o ?s) (gripper-empty) (not (in-gripper ?o)))))
