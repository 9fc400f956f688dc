; blind25 p06: a deep bin that holds one thing at a time. Typed; `empty` is
; derived (no item at the zone: `not` over `exists`); `place` needs the
; zone empty only where it is deep (a disjunctive precondition). Unit costs.
(define (domain deep-bin)
  (:requirements :strips :typing :negative-preconditions
                 :disjunctive-preconditions :existential-preconditions
                 :derived-predicates)
  (:types item zone)
  (:predicates (at ?x - item ?z - zone)
               (holding ?x - item)
               (handempty)
               (deep ?z - zone)
               (empty ?z - zone))

  (:derived (empty ?z - zone)
    (not (exists (?x - item) (at ?x ?z))))

  (:action pick
    :parameters (?x - item ?z - zone)
    :precondition (and (at ?x ?z) (handempty))
    :effect (and (holding ?x) (not (at ?x ?z)) (not (handempty))))

  (:action place
    :parameters (?x - item ?z - zone)
    :precondition (and (holding ?x) (or (not (deep ?z)) (empty ?z)))
    :effect (and (at ?x ?z) (handempty) (not (holding ?x)))))
