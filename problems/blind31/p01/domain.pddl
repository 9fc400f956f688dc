; blind31 p01: sort six coloured items into the bin of their colour, among
; distractors. Typed; derived (sorted ?o) with exists; a universal goal with
; imply; static colours.
(define (domain b31-sort)
  (:requirements :strips :typing :derived-predicates :existential-preconditions
                 :universal-preconditions :disjunctive-preconditions)
  (:types item colour place - object
          surface bin - place)
  (:predicates (at ?o - item ?p - place) (holding ?o - item) (handempty)
               (colour-of ?o - item ?c - colour) (bin-colour ?b - bin ?c - colour)
               (sortable ?o - item) (sorted ?o - item))
  (:derived (sorted ?o - item)
    (exists (?b - bin ?c - colour)
      (and (at ?o ?b) (colour-of ?o ?c) (bin-colour ?b ?c))))
  (:action pick
    :parameters (?o - item ?p - place)
    :precondition (and (at ?o ?p) (handempty))
    :effect (and (not (at ?o ?p)) (holding ?o) (not (handempty))))
  ; put something down on a plain surface (the counter)
  (:action place
    :parameters (?o - item ?s - surface)
    :precondition (holding ?o)
    :effect (and (at ?o ?s) (handempty) (not (holding ?o))))
  ; drop an item into a bin: only the bin of its own colour
  (:action drop
    :parameters (?o - item ?b - bin)
    :precondition (and (holding ?o)
                       (exists (?c - colour) (and (colour-of ?o ?c) (bin-colour ?b ?c))))
    :effect (and (at ?o ?b) (handempty) (not (holding ?o)))))
