; blind17 p02: untyped blocks on spots (xArm6). Static (block ?x) and
; (spot ?x) type the objects; a spot holds one block at most
; (negative precondition on occupied); stacking needs a clear support.
(define (domain stack-after-move)
  (:requirements :strips :negative-preconditions :equality)
  (:predicates (block ?x) (spot ?x)
               (at ?x ?s) (occupied ?s) (on ?x ?y) (clear ?x)
               (holding ?x) (handempty))

  (:action pick
    :parameters (?x ?s)
    :precondition (and (block ?x) (spot ?s) (at ?x ?s) (clear ?x) (handempty))
    :effect (and (not (at ?x ?s)) (not (occupied ?s)) (not (handempty))
                 (holding ?x)))

  (:action place
    :parameters (?x ?s)
    :precondition (and (block ?x) (spot ?s) (holding ?x) (not (occupied ?s)))
    :effect (and (not (holding ?x)) (handempty) (at ?x ?s) (occupied ?s)))

  (:action unstack
    :parameters (?x ?y)
    :precondition (and (block ?x) (block ?y) (on ?x ?y) (clear ?x) (handempty))
    :effect (and (not (on ?x ?y)) (clear ?y) (not (handempty)) (holding ?x)))

  (:action stack
    :parameters (?x ?y)
    :precondition (and (block ?x) (block ?y) (not (= ?x ?y))
                       (holding ?x) (clear ?y))
    :effect (and (not (holding ?x)) (handempty) (on ?x ?y) (not (clear ?y)))))
