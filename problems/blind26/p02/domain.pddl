; Panda: a crate the domain only lets the arm push (no pick action) is
; brought into a corner between two low walls. Spots are linked; each push
; has a cost read from a function of the two spots.
(define (domain b26-corner-push)
  (:requirements :strips :typing :equality :negative-preconditions
                 :action-costs)
  (:types crate spot)
  (:predicates (at ?c - crate ?s - spot) (link ?a ?b - spot))
  (:functions (total-cost) - number
              (push-cost ?a ?b - spot) - number)

  (:action push
    :parameters (?c - crate ?from ?to - spot)
    :precondition (and (at ?c ?from) (link ?from ?to) (not (= ?from ?to)))
    :effect (and (not (at ?c ?from)) (at ?c ?to)
                 (increase (total-cost) (push-cost ?from ?to)))))
