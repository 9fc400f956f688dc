;; Kitting and tool racking with typed items and three kinds of spot.
;; Parts go only into tray cells, tools only into rack slots, anything may
;; be set down on a table area; a cell or a slot holds one item
;; (`free`), an area any number.
(define (domain blind9-kit-rack)
  (:requirements :strips :typing :universal-preconditions
                 :existential-preconditions)
  (:types part tool - item
          cell slot area - spot
          item spot)
  (:predicates (at ?i - item ?s - spot)
               (holding ?i - item)
               (hand-empty)
               (free ?s - spot))
  (:action take
    :parameters (?i - item ?s - spot)
    :precondition (and (at ?i ?s) (hand-empty))
    :effect (and (not (at ?i ?s)) (not (hand-empty)) (holding ?i) (free ?s)))
  (:action kit
    :parameters (?p - part ?c - cell)
    :precondition (and (holding ?p) (free ?c))
    :effect (and (not (holding ?p)) (hand-empty) (at ?p ?c) (not (free ?c))))
  (:action hang
    :parameters (?t - tool ?s - slot)
    :precondition (and (holding ?t) (free ?s))
    :effect (and (not (holding ?t)) (hand-empty) (at ?t ?s) (not (free ?s))))
  (:action set-down
    :parameters (?i - item ?a - area)
    :precondition (holding ?i)
    :effect (and (not (holding ?i)) (hand-empty) (at ?i ?a))))
