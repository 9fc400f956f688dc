; blind15 p03: untyped blocks on zones, with negative preconditions
; (the hand is free when nothing is held: (not (busy))).
(define (domain xarm-unstack)
  (:requirements :strips :negative-preconditions)
  (:predicates (block ?b) (zone ?z) (at ?b ?z) (on ?a ?b)
               (clear ?b) (holding ?b) (busy))

  (:action pick-up
    :parameters (?b ?z)
    :precondition (and (block ?b) (zone ?z) (at ?b ?z) (clear ?b) (not (busy)))
    :effect (and (holding ?b) (busy) (not (at ?b ?z)) (not (clear ?b))))

  (:action put-down
    :parameters (?b ?z)
    :precondition (and (block ?b) (zone ?z) (holding ?b))
    :effect (and (at ?b ?z) (clear ?b) (not (holding ?b)) (not (busy))))

  (:action unstack
    :parameters (?a ?b)
    :precondition (and (block ?a) (block ?b) (on ?a ?b) (clear ?a) (not (busy)))
    :effect (and (holding ?a) (busy) (clear ?b) (not (on ?a ?b)) (not (clear ?a))))

  (:action stack
    :parameters (?a ?b)
    :precondition (and (block ?a) (block ?b) (holding ?a) (clear ?b))
    :effect (and (on ?a ?b) (clear ?a) (not (clear ?b)) (not (holding ?a)) (not (busy)))))
