; blind22 p04: typed blocks world on zones, with :equality (nothing stacked
; on itself) and a disjunctive goal (:disjunctive-preconditions): the cap
; may end either back on the slab or in the spare zone.
(define (domain cap-slab)
  (:requirements :strips :typing :equality :disjunctive-preconditions)
  (:types piece zone)
  (:predicates (on ?x - piece ?y - piece)
               (at ?x - piece ?z - zone)
               (clear ?x - piece)
               (holding ?x - piece)
               (handempty))

  (:action pick
    :parameters (?x - piece ?z - zone)
    :precondition (and (at ?x ?z) (clear ?x) (handempty))
    :effect (and (not (at ?x ?z)) (not (handempty)) (holding ?x)))

  (:action unstack
    :parameters (?x - piece ?y - piece)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (not (on ?x ?y)) (clear ?y) (not (handempty)) (holding ?x)))

  (:action put
    :parameters (?x - piece ?z - zone)
    :precondition (holding ?x)
    :effect (and (at ?x ?z) (not (holding ?x)) (handempty)))

  (:action stack
    :parameters (?x - piece ?y - piece)
    :precondition (and (holding ?x) (clear ?y) (not (= ?x ?y)))
    :effect (and (on ?x ?y) (not (clear ?y)) (not (holding ?x)) (handempty))))
