; blind31 p06: build two towers of three from a mixed pile. Typed with
; subtypes (a ball cannot carry anything), a derived (clear ?p) with a
; negated exists, :equality, :action-costs (stacking costs 2).
(define (domain b31-towers)
  (:requirements :strips :typing :negative-preconditions :derived-predicates
                 :existential-preconditions :equality :action-costs)
  (:types block ball - piece
          piece zone)
  (:predicates (at ?p - piece ?z - zone) (on ?p - piece ?q - piece)
               (holding ?p - piece) (handempty) (clear ?p - piece))
  (:functions (total-cost) - number)
  (:derived (clear ?p - piece) (not (exists (?x - piece) (on ?x ?p))))
  (:action pick
    :parameters (?p - piece ?z - zone)
    :precondition (and (at ?p ?z) (clear ?p) (handempty))
    :effect (and (not (at ?p ?z)) (holding ?p) (not (handempty))
                 (increase (total-cost) 1)))
  (:action unstack
    :parameters (?p - piece ?q - piece)
    :precondition (and (on ?p ?q) (clear ?p) (handempty))
    :effect (and (not (on ?p ?q)) (holding ?p) (not (handempty))
                 (increase (total-cost) 1)))
  (:action place
    :parameters (?p - piece ?z - zone)
    :precondition (holding ?p)
    :effect (and (at ?p ?z) (handempty) (not (holding ?p))
                 (increase (total-cost) 1)))
  (:action stack
    :parameters (?p - piece ?q - block)
    :precondition (and (holding ?p) (clear ?q) (not (= ?p ?q)))
    :effect (and (on ?p ?q) (handempty) (not (holding ?p))
                 (increase (total-cost) 2))))
