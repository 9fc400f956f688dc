;; blind10 p07: things moved between the levels of a shelf. Spots are
;; typed by level; one take schema, one put schema per level.
(define (domain blind10-shelf)
  (:requirements :strips :typing)
  (:types low high - spot
          spot thing)
  (:predicates (stands ?t - thing ?s - spot)
               (in-hand ?t - thing)
               (hand-free))
  (:action take
    :parameters (?t - thing ?s - spot)
    :precondition (and (stands ?t ?s) (hand-free))
    :effect (and (not (stands ?t ?s)) (not (hand-free)) (in-hand ?t)))
  (:action put-low
    :parameters (?t - thing ?s - low)
    :precondition (in-hand ?t)
    :effect (and (not (in-hand ?t)) (hand-free) (stands ?t ?s)))
  (:action put-high
    :parameters (?t - thing ?s - high)
    :precondition (in-hand ?t)
    :effect (and (not (in-hand ?t)) (hand-free) (stands ?t ?s))))
