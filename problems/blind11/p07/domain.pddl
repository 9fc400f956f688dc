;; blind11 p07: vessels (mugs, bottles) stand on sites (coasters, which
;; hold one vessel each, and worktops, which hold any number). Typed, with
;; a quantified goal in the problem.
(define (domain blind11-coasters)
  (:requirements :strips :typing :universal-preconditions
                 :existential-preconditions)
  (:types mug bottle - vessel
          coaster worktop - site
          vessel site)
  (:predicates (on-site ?v - vessel ?s - site)
               (unoccupied ?c - coaster)
               (holding ?v - vessel)
               (empty-hand))
  (:action pick-from-worktop
    :parameters (?v - vessel ?w - worktop)
    :precondition (and (on-site ?v ?w) (empty-hand))
    :effect (and (not (on-site ?v ?w)) (not (empty-hand)) (holding ?v)))
  (:action pick-from-coaster
    :parameters (?v - vessel ?c - coaster)
    :precondition (and (on-site ?v ?c) (empty-hand))
    :effect (and (not (on-site ?v ?c)) (unoccupied ?c) (not (empty-hand))
                 (holding ?v)))
  (:action set-on-coaster
    :parameters (?v - vessel ?c - coaster)
    :precondition (and (holding ?v) (unoccupied ?c))
    :effect (and (not (holding ?v)) (empty-hand) (on-site ?v ?c)
                 (not (unoccupied ?c))))
  (:action set-on-worktop
    :parameters (?v - vessel ?w - worktop)
    :precondition (holding ?v)
    :effect (and (not (holding ?v)) (empty-hand) (on-site ?v ?w))))
