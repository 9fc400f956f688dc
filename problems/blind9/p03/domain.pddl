;; Fixturing: a bar is gripped where it lies and seated in a slot. The
;; slot's shape (and so the yaw the bar must end at) is the geometry's.
(define (domain blind9-fixture)
  (:requirements :strips :typing)
  (:types bar location)
  (:predicates (lies ?b - bar ?l - location)
               (gripped ?b - bar)
               (idle))
  (:action grip
    :parameters (?b - bar ?l - location)
    :precondition (and (lies ?b ?l) (idle))
    :effect (and (not (lies ?b ?l)) (not (idle)) (gripped ?b)))
  (:action seat
    :parameters (?b - bar ?l - location)
    :precondition (gripped ?b)
    :effect (and (not (gripped ?b)) (idle) (lies ?b ?l))))
