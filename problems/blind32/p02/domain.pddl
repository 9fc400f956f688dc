; Mats on a table; the robot carries one item at a time between mats.
(define (domain mats)
  (:requirements :strips :typing)
  (:types item mat)
  (:predicates (on-mat ?o - item ?m - mat)
               (holding ?o - item)
               (handempty))
  (:action pick
    :parameters (?o - item ?m - mat)
    :precondition (and (on-mat ?o ?m) (handempty))
    :effect (and (not (on-mat ?o ?m)) (not (handempty)) (holding ?o)))
  (:action place
    :parameters (?o - item ?m - mat)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (on-mat ?o ?m))))
