; Packing with a top layer: items go into zones on the table, or onto
; another item (stacking). An item with something on it cannot be picked.
(define (domain pack-and-top)
  (:requirements :strips :typing :equality :negative-preconditions)
  (:types item zone)
  (:predicates (in ?o - item ?z - zone)
               (on ?o - item ?p - item)
               (clear ?o - item)
               (holding ?o - item)
               (handempty))
  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (in ?o ?z) (clear ?o) (handempty))
    :effect (and (not (in ?o ?z)) (not (handempty)) (holding ?o)))
  (:action put
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (in ?o ?z)))
  (:action take-off
    :parameters (?o - item ?p - item)
    :precondition (and (on ?o ?p) (clear ?o) (handempty))
    :effect (and (not (on ?o ?p)) (clear ?p) (not (handempty)) (holding ?o)))
  (:action put-on
    :parameters (?o - item ?p - item)
    :precondition (and (holding ?o) (clear ?p) (not (= ?o ?p)))
    :effect (and (not (holding ?o)) (handempty) (on ?o ?p) (not (clear ?p)))))
