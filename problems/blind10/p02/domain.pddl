;; blind10 p02: load a part into a container, or take it out.
;; "loose" places are table areas, "wells" are the floors of containers;
;; one grasp schema, two release schemas (one per kind of place).
(define (domain blind10-load)
  (:requirements :strips :typing)
  (:types well area - place
          place part)
  (:predicates (sits ?p - part ?l - place)
               (held ?p - part)
               (arm-free))
  (:action grab
    :parameters (?p - part ?l - place)
    :precondition (and (sits ?p ?l) (arm-free))
    :effect (and (not (sits ?p ?l)) (not (arm-free)) (held ?p)))
  (:action lower-into
    :parameters (?p - part ?w - well)
    :precondition (held ?p)
    :effect (and (not (held ?p)) (arm-free) (sits ?p ?w)))
  (:action set-on
    :parameters (?p - part ?a - area)
    :precondition (held ?p)
    :effect (and (not (held ?p)) (arm-free) (sits ?p ?a))))
