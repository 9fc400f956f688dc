; blind13 p05: a type hierarchy, a universally quantified goal; take / pack.
(define (domain panda-pack)
  (:requirements :strips :typing :universal-preconditions)
  (:types cube - item
          item spot)
  (:predicates (resting ?i - item ?s - spot)
               (gripping ?i - item)
               (idle))

  (:action take
    :parameters (?i - item ?s - spot)
    :precondition (and (resting ?i ?s) (idle))
    :effect (and (gripping ?i) (not (resting ?i ?s)) (not (idle))))

  (:action pack
    :parameters (?i - item ?s - spot)
    :precondition (gripping ?i)
    :effect (and (resting ?i ?s) (idle) (not (gripping ?i)))))
