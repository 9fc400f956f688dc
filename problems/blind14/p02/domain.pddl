; blind14 p02: swap two blocks between two one-block slots (xArm6).
; Untyped, static type predicates, a negative precondition: a slot holds
; one block at most, so the swap needs the third slot as a buffer.
(define (domain xarm-swap)
  (:requirements :strips :negative-preconditions)
  (:predicates (block ?x) (slot ?s)
               (at ?x ?s) (occupied ?s)
               (holding ?x) (handfree))

  (:action pick
    :parameters (?x ?s)
    :precondition (and (block ?x) (slot ?s) (at ?x ?s) (handfree))
    :effect (and (holding ?x) (not (at ?x ?s)) (not (occupied ?s))
                 (not (handfree))))

  (:action place
    :parameters (?x ?s)
    :precondition (and (block ?x) (slot ?s) (holding ?x) (not (occupied ?s)))
    :effect (and (at ?x ?s) (occupied ?s) (handfree) (not (holding ?x)))))
