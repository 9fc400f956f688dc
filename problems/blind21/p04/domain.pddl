; blind21 p04: typed blocks world with action costs that differ per object:
; lifting costs `(lift-cost ?x)` (the drum is heavy, the can light),
; setting down costs 1. `clear` keeps the stacking order symbolic.
(define (domain mixed-stack)
  (:requirements :strips :typing :equality :action-costs)
  (:types drum block can - piece
          piece zone)
  (:predicates (on ?x - piece ?y - piece)
               (on-zone ?x - piece ?z - zone)
               (clear ?x - piece)
               (holding ?x - piece)
               (handempty))
  (:functions (total-cost) - number
              (lift-cost ?x - piece) - number)

  (:action pick
    :parameters (?x - piece ?z - zone)
    :precondition (and (on-zone ?x ?z) (clear ?x) (handempty))
    :effect (and (not (on-zone ?x ?z)) (not (handempty)) (holding ?x)
                 (increase (total-cost) (lift-cost ?x))))

  (:action unstack
    :parameters (?x - piece ?y - piece)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (not (on ?x ?y)) (clear ?y) (not (handempty)) (holding ?x)
                 (increase (total-cost) (lift-cost ?x))))

  (:action put
    :parameters (?x - piece ?z - zone)
    :precondition (holding ?x)
    :effect (and (on-zone ?x ?z) (not (holding ?x)) (handempty)
                 (increase (total-cost) 1)))

  (:action stack
    :parameters (?x - piece ?y - piece)
    :precondition (and (holding ?x) (clear ?y) (not (= ?x ?y)))
    :effect (and (on ?x ?y) (not (clear ?y)) (not (holding ?x)) (handempty)
                 (increase (total-cost) 1))))
