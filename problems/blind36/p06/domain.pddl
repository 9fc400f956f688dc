; blind36 p06: capacity-one spots and open stores, with action costs.
(define (domain swap-costs)
  (:requirements :strips :typing :action-costs)
  (:types item place - object
          spot store - place)
  (:predicates (at ?o - item ?p - place)
               (holding ?o - item)
               (handempty)
               (free ?s - spot))
  (:functions (total-cost) - number)
  (:action pick-spot
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (holding ?o) (free ?s) (not (at ?o ?s)) (not (handempty))
                 (increase (total-cost) 1)))
  (:action pick-store
    :parameters (?o - item ?p - store)
    :precondition (and (at ?o ?p) (handempty))
    :effect (and (holding ?o) (not (at ?o ?p)) (not (handempty))
                 (increase (total-cost) 1)))
  (:action place-spot
    :parameters (?o - item ?s - spot)
    :precondition (and (holding ?o) (free ?s))
    :effect (and (at ?o ?s) (handempty) (not (free ?s)) (not (holding ?o))
                 (increase (total-cost) 1)))
  (:action place-store
    :parameters (?o - item ?p - store)
    :precondition (holding ?o)
    :effect (and (at ?o ?p) (handempty) (not (holding ?o))
                 (increase (total-cost) 3))))
