; blind25 p05: dishes on dishes. Typed, with action costs: taking a thing
; off another thing, or putting it onto one, costs 2 (care); to or from a
; spot on the table costs 1.
(define (domain dish-stack)
  (:requirements :strips :typing :action-costs)
  (:types item spot)
  (:predicates (at ?x - item ?s - spot)
               (on ?x - item ?y - item)
               (clear ?x - item)
               (holding ?x - item)
               (handempty))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?x - item ?s - spot)
    :precondition (and (at ?x ?s) (clear ?x) (handempty))
    :effect (and (holding ?x) (not (at ?x ?s)) (not (clear ?x))
                 (not (handempty)) (increase (total-cost) 1)))

  (:action put
    :parameters (?x - item ?s - spot)
    :precondition (holding ?x)
    :effect (and (at ?x ?s) (clear ?x) (handempty) (not (holding ?x))
                 (increase (total-cost) 1)))

  (:action unstack
    :parameters (?x - item ?y - item)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (holding ?x) (clear ?y) (not (on ?x ?y)) (not (clear ?x))
                 (not (handempty)) (increase (total-cost) 2)))

  (:action stack
    :parameters (?x - item ?y - item)
    :precondition (and (holding ?x) (clear ?y))
    :effect (and (on ?x ?y) (clear ?x) (not (clear ?y)) (handempty)
                 (not (holding ?x)) (increase (total-cost) 2))))
