; PDDLStream's Kuka kitchen (caelan/pddlstream, examples/pybullet/kuka) on a
; Franka Panda: clean an item at the sink, cook it at the stove, and bring
; the arm back home. The arm must be at a region (its hand above it) to pick
; or place there; clean and cook are symbolic only.
(define (domain arm-kitchen)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types item region)
  (:predicates (at ?i - item ?r - region)
               (arm-at ?r - region)
               (holding ?i - item)
               (handempty)
               (is-sink ?r - region)
               (is-stove ?r - region)
               (cleaned ?i - item)
               (cooked ?i - item))

  (:action move
    :parameters (?from - region ?to - region)
    :precondition (and (arm-at ?from) (not (= ?from ?to)))
    :effect (and (not (arm-at ?from)) (arm-at ?to)))

  (:action pick
    :parameters (?i - item ?r - region)
    :precondition (and (at ?i ?r) (arm-at ?r) (handempty))
    :effect (and (not (at ?i ?r)) (not (handempty)) (holding ?i)))

  (:action place
    :parameters (?i - item ?r - region)
    :precondition (and (holding ?i) (arm-at ?r))
    :effect (and (not (holding ?i)) (handempty) (at ?i ?r)))

  (:action clean
    :parameters (?i - item ?r - region)
    :precondition (and (at ?i ?r) (is-sink ?r))
    :effect (cleaned ?i))

  (:action cook
    :parameters (?i - item ?r - region)
    :precondition (and (at ?i ?r) (is-stove ?r) (cleaned ?i))
    :effect (cooked ?i)))
