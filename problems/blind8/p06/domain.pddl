;; Packing boxes into a tray, one at a time.
(define (domain blind8-pack)
  (:requirements :strips :typing)
  (:types box spot)
  (:predicates (at ?b - box ?s - spot)
               (holding ?b - box)
               (handempty))
  (:action pick
    :parameters (?b - box ?s - spot)
    :precondition (and (at ?b ?s) (handempty))
    :effect (and (not (at ?b ?s)) (not (handempty)) (holding ?b)))
  (:action place
    :parameters (?b - box ?s - spot)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (at ?b ?s))))
