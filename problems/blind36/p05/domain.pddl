; blind36 p05: the same typed pick-and-place as p01, under other names.
(define (domain serve)
  (:requirements :strips :typing :disjunctive-preconditions)
  (:types item region)
  (:predicates (at ?o - item ?r - region)
               (holding ?o - item)
               (handempty))
  (:action grab
    :parameters (?o - item ?r - region)
    :precondition (and (at ?o ?r) (handempty))
    :effect (and (holding ?o) (not (at ?o ?r)) (not (handempty))))
  (:action release
    :parameters (?o - item ?r - region)
    :precondition (holding ?o)
    :effect (and (at ?o ?r) (handempty) (not (holding ?o)))))
