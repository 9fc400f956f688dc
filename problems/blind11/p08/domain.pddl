;; blind11 p08: parts on pads, one part a pad; a part is raised off its pad
;; and lowered onto an empty one.
(define (domain blind11-rotate)
  (:requirements :strips :typing)
  (:types part pad)
  (:predicates (occupies ?x - part ?p - pad)
               (empty ?p - pad)
               (raised ?x - part)
               (gripper-open))
  (:action raise
    :parameters (?x - part ?p - pad)
    :precondition (and (occupies ?x ?p) (gripper-open))
    :effect (and (not (occupies ?x ?p)) (empty ?p) (not (gripper-open))
                 (raised ?x)))
  (:action lower
    :parameters (?x - part ?p - pad)
    :precondition (and (raised ?x) (empty ?p))
    :effect (and (not (raised ?x)) (gripper-open) (occupies ?x ?p)
                 (not (empty ?p)))))
