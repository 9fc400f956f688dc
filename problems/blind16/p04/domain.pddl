; blind16 p04: untyped pick / place with static type predicates and one
; object per spot (xArm6). A spot is free or holds one cube.
(define (domain xarm-swap)
  (:requirements :strips :negative-preconditions)
  (:predicates (cube ?o) (spot ?s)
               (at ?o ?s) (occupied ?s)
               (holding ?o) (busy))

  (:action pick
    :parameters (?o ?s)
    :precondition (and (cube ?o) (spot ?s) (at ?o ?s) (not (busy)))
    :effect (and (not (at ?o ?s)) (not (occupied ?s))
                 (busy) (holding ?o)))

  (:action place
    :parameters (?o ?s)
    :precondition (and (cube ?o) (spot ?s) (holding ?o)
                       (not (occupied ?s)))
    :effect (and (not (holding ?o)) (not (busy))
                 (at ?o ?s) (occupied ?s))))
