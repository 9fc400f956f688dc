; blind33 p02: the planar disk, suction grab/drop between zones.
(define (domain b33-p02)
  (:requirements :strips :typing)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone) (holding ?o - item) (free))
  (:action grab
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (free))
    :effect (and (holding ?o) (not (at ?o ?z)) (not (free))))
  (:action drop
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (free) (not (holding ?o)))))
