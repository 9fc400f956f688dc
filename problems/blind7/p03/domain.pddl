;; A courier disk fetches cargo by suction and drops it at a spot. Typed:
;; crates are cargo, docks are spots.
(define (domain blind7-courier)
  (:requirements :typing :negative-preconditions :action-costs)
  (:types cargo spot - object
          crate - cargo
          dock - spot)
  (:predicates (lies ?c - cargo ?s - spot)
               (attached ?c - cargo)
               (suction-on))
  (:functions (total-cost) - number)
  (:action fetch
    :parameters (?c - cargo ?s - spot)
    :precondition (and (lies ?c ?s) (not (suction-on)))
    :effect (and (not (lies ?c ?s)) (attached ?c) (suction-on)
                 (increase (total-cost) 1)))
  (:action drop
    :parameters (?c - cargo ?s - spot)
    :precondition (attached ?c)
    :effect (and (not (attached ?c)) (not (suction-on)) (lies ?c ?s)
                 (increase (total-cost) 1))))
