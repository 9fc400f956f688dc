; blind15 p04: typed hierarchy with action costs. A bottle stands on a
; fixture (a place onto a body), anything goes into a zone.
(define (domain tall-and-thin)
  (:requirements :strips :typing :action-costs)
  (:types bottle bar - item item fixture zone)
  (:predicates (at ?o - item ?z - zone)
               (standing-on ?o - bottle ?f - fixture)
               (holding ?o - item)
               (handempty))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (holding ?o) (not (at ?o ?z)) (not (handempty))
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (handempty) (not (holding ?o))
                 (increase (total-cost) 1)))

  (:action stand
    :parameters (?o - bottle ?f - fixture)
    :precondition (holding ?o)
    :effect (and (standing-on ?o ?f) (handempty) (not (holding ?o))
                 (increase (total-cost) 2))))
