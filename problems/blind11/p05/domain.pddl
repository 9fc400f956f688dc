;; blind11 p05: pieces sit on pads or perch on one another. Only a bare
;; piece (nothing perched on it) may be lifted or perched upon.
(define (domain blind11-stack)
  (:requirements :strips :typing)
  (:types piece pad)
  (:predicates (sits ?x - piece ?p - pad)
               (perched ?x - piece ?y - piece)
               (bare ?x - piece)
               (lifted ?x - piece)
               (idle))
  (:action lift
    :parameters (?x - piece ?p - pad)
    :precondition (and (sits ?x ?p) (bare ?x) (idle))
    :effect (and (not (sits ?x ?p)) (not (idle)) (lifted ?x)))
  (:action lift-off
    :parameters (?x - piece ?y - piece)
    :precondition (and (perched ?x ?y) (bare ?x) (idle))
    :effect (and (not (perched ?x ?y)) (bare ?y) (not (idle)) (lifted ?x)))
  (:action settle
    :parameters (?x - piece ?p - pad)
    :precondition (lifted ?x)
    :effect (and (not (lifted ?x)) (idle) (sits ?x ?p)))
  (:action perch
    :parameters (?x - piece ?y - piece)
    :precondition (and (lifted ?x) (bare ?y))
    :effect (and (not (lifted ?x)) (idle) (perched ?x ?y) (not (bare ?y)))))
