; Problems written to test the planner rather than to show it: a planar
; suction disk moves blocks between rectangular regions of a bench. The
; symbolic level knows only which region a block is in -- no `clear`, no
; capacity, no adjacency -- so whether a block fits, whether a blocker must
; leave first, and whether a passage is wide enough are facts of geometry
; alone, found by trajectory optimization.
(define (domain robust-planar)
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
