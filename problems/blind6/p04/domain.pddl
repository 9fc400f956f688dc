; An inspection station. The arm must be at a spot (its hand above it) to
; pick, place, open, scan or press there. A spot with a lid takes nothing
; until it is opened, with the hand empty. A part is scanned while held over
; the scanner; the button seals the bin once a scanned part lies in it.
; open, scan and press are symbolic: they move nothing.
(define (domain blind6-station)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types part spot)
  (:predicates (at ?p - part ?s - spot)
               (arm-at ?s - spot)
               (holding ?p - part)
               (hand-empty)
               (has-lid ?s - spot)
               (accessible ?s - spot)
               (is-scanner ?s - spot)
               (is-button ?s - spot)
               (is-bin ?s - spot)
               (scanned ?p - part)
               (sealed))
  (:action move
    :parameters (?from - spot ?to - spot)
    :precondition (and (arm-at ?from) (not (= ?from ?to)))
    :effect (and (not (arm-at ?from)) (arm-at ?to)))
  (:action pick
    :parameters (?p - part ?s - spot)
    :precondition (and (at ?p ?s) (arm-at ?s) (hand-empty) (accessible ?s))
    :effect (and (not (at ?p ?s)) (not (hand-empty)) (holding ?p)))
  (:action place
    :parameters (?p - part ?s - spot)
    :precondition (and (holding ?p) (arm-at ?s) (accessible ?s))
    :effect (and (not (holding ?p)) (hand-empty) (at ?p ?s)))
  (:action open
    :parameters (?s - spot)
    :precondition (and (arm-at ?s) (hand-empty) (has-lid ?s) (not (accessible ?s)))
    :effect (accessible ?s))
  (:action scan
    :parameters (?p - part ?s - spot)
    :precondition (and (holding ?p) (arm-at ?s) (is-scanner ?s))
    :effect (scanned ?p))
  (:action press
    :parameters (?p - part ?b - spot ?s - spot)
    :precondition (and (arm-at ?s) (is-button ?s) (hand-empty)
                       (at ?p ?b) (is-bin ?b) (scanned ?p))
    :effect (sealed)))
