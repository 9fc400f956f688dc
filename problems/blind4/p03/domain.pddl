; Pick, place and stack: things go into regions or onto each other. Whether
; a thing fits on top of another, and stands there, is left to the geometry.
(define (domain blind4-tower)
  (:requirements :strips :typing)
  (:types piece region)
  (:predicates (in ?p - piece ?r - region)
               (on ?p - piece ?q - piece)
               (top ?p - piece)
               (holding ?p - piece)
               (free))
  (:action pick
    :parameters (?p - piece ?r - region)
    :precondition (and (in ?p ?r) (top ?p) (free))
    :effect (and (not (in ?p ?r)) (not (top ?p)) (not (free)) (holding ?p)))
  (:action place
    :parameters (?p - piece ?r - region)
    :precondition (holding ?p)
    :effect (and (not (holding ?p)) (free) (top ?p) (in ?p ?r)))
  (:action unstack
    :parameters (?p - piece ?q - piece)
    :precondition (and (on ?p ?q) (top ?p) (free))
    :effect (and (not (on ?p ?q)) (not (top ?p)) (not (free)) (holding ?p) (top ?q)))
  (:action stack
    :parameters (?p - piece ?q - piece)
    :precondition (and (holding ?p) (top ?q))
    :effect (and (not (holding ?p)) (not (top ?q)) (free) (top ?p) (on ?p ?q))))
