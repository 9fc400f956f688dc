;; Nut stacking: pieces sit in zones or on other pieces. A piece with
;; something on it is covered (negative preconditions keep covered pieces
;; from being seized or built on).
(define (domain blind7-nuts)
  (:requirements :typing :negative-preconditions :equality :action-costs)
  (:types piece zone - object
          nut washer - piece)
  (:predicates (placed ?p - piece ?z - zone)
               (stacked-on ?p - piece ?q - piece)
               (covered ?p - piece)
               (in-hand ?p - piece)
               (hand-occupied))
  (:functions (total-cost) - number)
  (:action seize
    :parameters (?p - piece ?z - zone)
    :precondition (and (placed ?p ?z) (not (covered ?p)) (not (hand-occupied)))
    :effect (and (not (placed ?p ?z)) (in-hand ?p) (hand-occupied)
                 (increase (total-cost) 1)))
  (:action seize-off
    :parameters (?p - piece ?q - piece)
    :precondition (and (stacked-on ?p ?q) (not (covered ?p)) (not (hand-occupied)))
    :effect (and (not (stacked-on ?p ?q)) (not (covered ?q)) (in-hand ?p)
                 (hand-occupied) (increase (total-cost) 1)))
  (:action deposit
    :parameters (?p - piece ?z - zone)
    :precondition (in-hand ?p)
    :effect (and (not (in-hand ?p)) (not (hand-occupied)) (placed ?p ?z)
                 (increase (total-cost) 1)))
  (:action mount
    :parameters (?p - piece ?q - piece)
    :precondition (and (in-hand ?p) (not (covered ?q)) (not (= ?p ?q)))
    :effect (and (not (in-hand ?p)) (not (hand-occupied)) (stacked-on ?p ?q)
                 (covered ?q) (increase (total-cost) 2))))
