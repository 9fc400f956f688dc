; blind14 p06: clear a work area of every item (xArm6). The goal is a
; forall over a negated fact; any bin may take any item.
(define (domain xarm-clear)
  (:requirements :strips :typing :negative-preconditions
                 :universal-preconditions)
  (:types item area)
  (:predicates (in ?o - item ?a - area)
               (carrying ?o - item)
               (handfree))

  (:action grab
    :parameters (?o - item ?a - area)
    :precondition (and (in ?o ?a) (handfree))
    :effect (and (carrying ?o) (not (in ?o ?a)) (not (handfree))))

  (:action release
    :parameters (?o - item ?a - area)
    :precondition (carrying ?o)
    :effect (and (in ?o ?a) (handfree) (not (carrying ?o)))))
