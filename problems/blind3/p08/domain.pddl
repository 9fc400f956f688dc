; An arm brings an object to a region by picking and placing it (cost 1 + 1)
; or by pushing it (cost 3). The domain does not say whether the object can
; be lifted: that is the gripper's business.
(define (domain blind3-arm-push)
  (:requirements :strips :typing :action-costs)
  (:types obj region)
  (:predicates (at ?o - obj ?r - region) (holding ?o - obj) (handempty))
  (:functions (total-cost) - number)
  (:action pick
    :parameters (?o - obj ?r - region)
    :precondition (and (at ?o ?r) (handempty))
    :effect (and (not (at ?o ?r)) (not (handempty)) (holding ?o) (increase (total-cost) 1)))
  (:action place
    :parameters (?o - obj ?r - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?r) (increase (total-cost) 1)))
  (:action push
    :parameters (?o - obj ?from - region ?to - region)
    :precondition (and (at ?o ?from) (handempty))
    :effect (and (not (at ?o ?from)) (at ?o ?to) (increase (total-cost) 3))))
