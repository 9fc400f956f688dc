(define (domain geo-test)
  (:requirements :strips :typing)
  (:types block surface - object region - surface)
  (:predicates (on ?b - block ?s - surface) (clear ?x - object) (holding ?b - block) (handempty))
  (:action pick
    :parameters (?b - block ?from - surface)
    :precondition (and (on ?b ?from) (clear ?b) (handempty))
    :effect (and (holding ?b) (not (on ?b ?from)) (not (handempty))))
  (:action place
    :parameters (?b - block ?to - surface)
    :precondition (holding ?b)
    :effect (and (on ?b ?to) (handempty) (not (holding ?b))))
  (:action wait
    :parameters ()
    :precondition (handempty)
    :effect (handempty)))
