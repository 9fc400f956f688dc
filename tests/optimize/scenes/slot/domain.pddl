;; Fetching from a shelf: containers are taken from and set at places.
(define (domain blind8-fetch)
  (:requirements :strips :typing)
  (:types container place)
  (:predicates (at ?c - container ?p - place)
               (in-hand ?c - container)
               (empty-hand))
  (:action take
    :parameters (?c - container ?p - place)
    :precondition (and (at ?c ?p) (empty-hand))
    :effect (and (not (at ?c ?p)) (not (empty-hand)) (in-hand ?c)))
  (:action set
    :parameters (?c - container ?p - place)
    :precondition (in-hand ?c)
    :effect (and (not (in-hand ?c)) (empty-hand) (at ?c ?p))))
