; A disk robot that can only push: a block goes from one zone to another by
; sliding over the bench. Which pushes are possible (direction, what is in
; the way) is left to the geometry.
(define (domain blind6-shove)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types block zone)
  (:predicates (in ?b - block ?z - zone))
  (:action push
    :parameters (?b - block ?from - zone ?to - zone)
    :precondition (and (in ?b ?from) (not (= ?from ?to)))
    :effect (and (not (in ?b ?from)) (in ?b ?to))))
