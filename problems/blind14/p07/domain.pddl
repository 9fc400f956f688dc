; blind14 p07: move three items from the near zone to either far zone
; (KUKA iiwa turned 90 deg). The goal is a derived predicate: an item is
; stored when it is in some far zone.
(define (domain kuka-store)
  (:requirements :strips :typing :derived-predicates
                 :existential-preconditions)
  (:types item zone)
  (:predicates (in ?o - item ?z - zone)
               (holding ?o - item)
               (handfree)
               (far ?z - zone)
               (stored ?o - item))

  (:derived (stored ?o - item)
    (exists (?z - zone) (and (in ?o ?z) (far ?z))))

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (in ?o ?z) (handfree))
    :effect (and (holding ?o) (not (in ?o ?z)) (not (handfree))))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (in ?o ?z) (handfree) (not (holding ?o)))))
