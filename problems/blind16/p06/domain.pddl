; blind16 p06: typed pick / place with action costs (KUKA iiwa):
; a pick costs 2, a place 1.
(define (domain kuka-wall)
  (:requirements :strips :typing :action-costs)
  (:types item area)
  (:predicates (at ?o - item ?a - area)
               (holding ?o - item)
               (handempty))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?o - item ?a - area)
    :precondition (and (at ?o ?a) (handempty))
    :effect (and (not (at ?o ?a)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 2)))

  (:action place
    :parameters (?o - item ?a - area)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?a)
                 (increase (total-cost) 1))))
