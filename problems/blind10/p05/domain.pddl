;; blind10 p05: sort items into bins by kind. Each kind has its own bin
;; type and its own binning action, so typing alone keeps a can out of
;; the cube bin; any item may also be set down on a mat.
(define (domain blind10-sort)
  (:requirements :strips :typing :universal-preconditions :existential-preconditions)
  (:types can cube bar - item
          can-bin cube-bin bar-bin - bin
          bin mat - area
          item area)
  (:predicates (lies ?i - item ?a - area)
               (hand-holds ?i - item)
               (hand-empty))
  (:action pick-up
    :parameters (?i - item ?a - area)
    :precondition (and (lies ?i ?a) (hand-empty))
    :effect (and (not (lies ?i ?a)) (not (hand-empty)) (hand-holds ?i)))
  (:action bin-can
    :parameters (?c - can ?b - can-bin)
    :precondition (hand-holds ?c)
    :effect (and (not (hand-holds ?c)) (hand-empty) (lies ?c ?b)))
  (:action bin-cube
    :parameters (?c - cube ?b - cube-bin)
    :precondition (hand-holds ?c)
    :effect (and (not (hand-holds ?c)) (hand-empty) (lies ?c ?b)))
  (:action bin-bar
    :parameters (?r - bar ?b - bar-bin)
    :precondition (hand-holds ?r)
    :effect (and (not (hand-holds ?r)) (hand-empty) (lies ?r ?b)))
  (:action set-down
    :parameters (?i - item ?m - mat)
    :precondition (hand-holds ?i)
    :effect (and (not (hand-holds ?i)) (hand-empty) (lies ?i ?m))))
