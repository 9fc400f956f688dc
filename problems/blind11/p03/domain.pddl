;; blind11 p03: containers are taken from an area and put into another;
;; the hand holds one at a time.
(define (domain blind11-cans)
  (:requirements :strips :typing)
  (:types container area)
  (:predicates (inside ?c - container ?a - area)
               (held ?c - container)
               (hand-free))
  (:action take
    :parameters (?c - container ?a - area)
    :precondition (and (inside ?c ?a) (hand-free))
    :effect (and (not (inside ?c ?a)) (not (hand-free)) (held ?c)))
  (:action put
    :parameters (?c - container ?a - area)
    :precondition (held ?c)
    :effect (and (not (held ?c)) (hand-free) (inside ?c ?a))))
