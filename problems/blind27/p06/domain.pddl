; Panda: untyped, :strips only; the rack's slots and the bench spot are
; constants of the domain.
(define (domain b27-rack)
  (:requirements :strips)
  (:constants s1 s2 s3 bench)
  (:predicates (part ?x) (spot ?s) (at ?x ?s) (holding ?x) (handempty))
  (:action take
    :parameters (?x ?s)
    :precondition (and (part ?x) (at ?x ?s) (handempty))
    :effect (and (not (at ?x ?s)) (not (handempty)) (holding ?x)))
  (:action insert
    :parameters (?x ?s)
    :precondition (and (spot ?s) (holding ?x))
    :effect (and (at ?x ?s) (handempty) (not (holding ?x)))))
