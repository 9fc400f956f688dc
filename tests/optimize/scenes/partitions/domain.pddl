; A copy of domains/robust-planar: a planar suction disk moves blocks between
; regions of a bench; pick and place only, so a carry is the only way across.
(define (domain partitions)
  (:requirements :strips :typing)
  (:types block region)
  (:predicates (in ?b - block ?r - region)
               (holding ?b - block)
               (handempty))

  (:action pick
    :parameters (?b - block ?r - region)
    :precondition (and (in ?b ?r) (handempty))
    :effect (and (not (in ?b ?r)) (not (handempty)) (holding ?b)))

  (:action place
    :parameters (?b - block ?r - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (in ?b ?r))))
