; blind24 p03: typed pick-and-place with a type hierarchy and action costs:
; a pick costs the object's (lift-cost ?o), a place 1.
(define (domain long-and-tiny)
  (:requirements :strips :typing :action-costs)
  (:types rod die - item item zone)
  (:predicates (at ?o - item ?z - zone)
               (holding ?o - item)
               (handempty))
  (:functions (total-cost) - number
              (lift-cost ?o - item) - number)

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (not (at ?o ?z)) (not (handempty)) (holding ?o)
                 (increase (total-cost) (lift-cost ?o))))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (handempty) (not (holding ?o))
                 (increase (total-cost) 1))))
