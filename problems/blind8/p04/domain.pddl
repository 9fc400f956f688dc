;; A mobile disk with a suction cup moves loads between areas. Whether a
;; load is in the way is the geometry's to find out.
(define (domain blind8-haul)
  (:requirements :strips :typing)
  (:types load area)
  (:predicates (at ?l - load ?a - area)
               (attached ?l - load)
               (unloaded))
  (:action attach
    :parameters (?l - load ?a - area)
    :precondition (and (at ?l ?a) (unloaded))
    :effect (and (not (at ?l ?a)) (not (unloaded)) (attached ?l)))
  (:action detach
    :parameters (?l - load ?a - area)
    :precondition (attached ?l)
    :effect (and (not (attached ?l)) (unloaded) (at ?l ?a))))
