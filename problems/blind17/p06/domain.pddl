; blind17 p06: typed pick / place (Panda); the sorting rule lives in the
; goal, written with forall and imply over a static attribute (long ?o).
(define (domain sort-by-length)
  (:requirements :strips :typing :negative-preconditions
                 :disjunctive-preconditions :universal-preconditions)
  (:types item spot)
  (:predicates (at ?o - item ?s - spot)
               (long ?o - item)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?s - spot)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?s))))
