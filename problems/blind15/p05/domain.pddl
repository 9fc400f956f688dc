; blind15 p05: typed; each item has a static destination, and the goal is
; quantified over the items (forall / exists).
(define (domain kuka-reach)
  (:requirements :strips :typing :universal-preconditions :existential-preconditions)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone)
               (dest ?o - item ?z - zone)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (holding ?o) (not (at ?o ?z)) (not (handempty))))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (handempty) (not (holding ?o)))))
