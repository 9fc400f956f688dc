; KUKA iiwa: a locker region is locked until the arm "presses" a button
; pad (a move of the empty hand over the pad); then the cube may be taken
; out and put on the goal. Untyped, static type predicates, negative
; preconditions.
(define (domain b26-button)
  (:requirements :strips :negative-preconditions)
  (:predicates (at ?o ?r) (holding ?o) (handempty)
               (cube ?o) (zone ?r) (button ?b) (opens ?b ?r)
               (locked ?r))

  (:action press
    :parameters (?b ?r)
    :precondition (and (button ?b) (opens ?b ?r) (handempty) (locked ?r))
    :effect (not (locked ?r)))

  (:action pick
    :parameters (?o ?r)
    :precondition (and (cube ?o) (zone ?r) (at ?o ?r) (handempty)
                       (not (locked ?r)))
    :effect (and (not (at ?o ?r)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o ?r)
    :precondition (and (holding ?o) (zone ?r))
    :effect (and (not (holding ?o)) (handempty) (at ?o ?r))))
