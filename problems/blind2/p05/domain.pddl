; A planar suction disk moves blocks between regions of a bench. The symbolic
; level knows only which region a block is in: no clear, no capacity, no
; adjacency. Whether a block fits a region, whether another must leave first
; and which way the disk can go are facts of geometry.
(define (domain blind2-planar)
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
