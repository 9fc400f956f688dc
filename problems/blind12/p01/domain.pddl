;; blind12 p01: a piece is grabbed from the spot it sits on and released
;; onto another spot. One piece in hand at a time.
(define (domain blind12-slab)
  (:requirements :strips :typing)
  (:types piece spot)
  (:predicates (sits ?p - piece ?s - spot)
               (held ?p - piece)
               (empty-hand))
  (:action grab
    :parameters (?p - piece ?s - spot)
    :precondition (and (sits ?p ?s) (empty-hand))
    :effect (and (held ?p) (not (sits ?p ?s)) (not (empty-hand))))
  (:action release
    :parameters (?p - piece ?s - spot)
    :precondition (held ?p)
    :effect (and (sits ?p ?s) (empty-hand) (not (held ?p)))))
