;; Colour sorting with a derived predicate: an item is sorted when it
;; rests in a zone of its own colour. The goal says "every item sorted"
;; (forall), never where each one goes.
(define (domain blind9-sorting)
  (:requirements :strips :typing :derived-predicates
                 :existential-preconditions :universal-preconditions)
  (:types item zone colour)
  (:predicates (at ?o - item ?z - zone)
               (holding ?o - item)
               (empty-hand)
               (item-colour ?o - item ?c - colour)
               (zone-colour ?z - zone ?c - colour)
               (sorted ?o - item))
  (:derived (sorted ?o - item)
    (exists (?z - zone ?c - colour)
      (and (at ?o ?z) (item-colour ?o ?c) (zone-colour ?z ?c))))
  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (empty-hand))
    :effect (and (not (at ?o ?z)) (not (empty-hand)) (holding ?o)))
  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (empty-hand) (at ?o ?z))))
