; blind25 p03: planar sorting by colour. Typed; `sorted` is derived (an item
; is sorted when it stands in a zone that takes its colour: `exists`), and
; the goal asks it of every item (`forall`). Unit costs.
(define (domain planar-sort)
  (:requirements :strips :typing :derived-predicates
                 :existential-preconditions :universal-preconditions)
  (:types item zone colour)
  (:predicates (at ?o - item ?z - zone)
               (holding ?o - item)
               (handempty)
               (colour-of ?o - item ?c - colour)
               (takes ?z - zone ?c - colour)
               (sorted ?o - item))

  (:derived (sorted ?o - item)
    (exists (?z - zone ?c - colour)
      (and (at ?o ?z) (colour-of ?o ?c) (takes ?z ?c))))

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (not (at ?o ?z)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (handempty) (not (holding ?o)))))
