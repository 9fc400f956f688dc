; KUKA iiwa: untyped, static type predicates, IPC style.
(define (domain b27-tray)
  (:requirements :strips :equality)
  (:predicates (cube ?x) (place ?p) (at ?x ?p) (holding ?x) (handempty))
  (:action pick
    :parameters (?x ?p)
    :precondition (and (cube ?x) (place ?p) (at ?x ?p) (handempty))
    :effect (and (not (at ?x ?p)) (not (handempty)) (holding ?x)))
  (:action drop
    :parameters (?x ?p)
    :precondition (and (cube ?x) (place ?p) (holding ?x))
    :effect (and (at ?x ?p) (handempty) (not (holding ?x)))))
