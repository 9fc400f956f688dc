; A Panda picks cubes from a table and places them in regions (render tests).
(define (domain render-panda)
  (:requirements :strips :typing)
  (:types cube place)
  (:predicates (on ?c - cube ?p - place) (holding ?c - cube) (handempty))
  (:action pick
    :parameters (?c - cube ?p - place)
    :precondition (and (on ?c ?p) (handempty))
    :effect (and (holding ?c) (not (on ?c ?p)) (not (handempty))))
  (:action place
    :parameters (?c - cube ?p - place)
    :precondition (holding ?c)
    :effect (and (on ?c ?p) (handempty) (not (holding ?c))))
  (:action note
    :parameters (?c - cube)
    :precondition (handempty)
    :effect (handempty)))
