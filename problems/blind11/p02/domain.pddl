;; blind11 p02: items stand in places (table spots, places in a row on a
;; shelf board); an item is grabbed and slotted into a free place.
(define (domain blind11-row)
  (:requirements :strips :typing :negative-preconditions)
  (:types item place)
  (:predicates (stands ?i - item ?p - place)
               (taken ?p - place)
               (carrying ?i - item)
               (free-hand))
  (:action grab
    :parameters (?i - item ?p - place)
    :precondition (and (stands ?i ?p) (free-hand))
    :effect (and (not (stands ?i ?p)) (not (taken ?p)) (not (free-hand))
                 (carrying ?i)))
  (:action slot-in
    :parameters (?i - item ?p - place)
    :precondition (and (carrying ?i) (not (taken ?p)))
    :effect (and (not (carrying ?i)) (free-hand) (stands ?i ?p) (taken ?p))))
