;; blind12 p06: a type hierarchy (tins and battens are items); items are
;; collected from where they stand and stored on a pad.
(define (domain blind12-store)
  (:requirements :strips :typing)
  (:types tin batten - item
          item pad)
  (:predicates (at ?i - item ?p - pad)
               (holding ?i - item)
               (hand-empty))
  (:action collect
    :parameters (?i - item ?p - pad)
    :precondition (and (at ?i ?p) (hand-empty))
    :effect (and (holding ?i) (not (at ?i ?p)) (not (hand-empty))))
  (:action store
    :parameters (?i - item ?p - pad)
    :precondition (holding ?i)
    :effect (and (at ?i ?p) (hand-empty) (not (holding ?i)))))
