; blind13 p06: typed blocksworld-style stacking on a drum; equality.
(define (domain kuka-tower)
  (:requirements :strips :typing :equality)
  (:types block drum - support
          support area)
  (:predicates (in-area ?b - block ?a - area)
               (on ?b - block ?s - support)
               (clear ?s - support)
               (holding ?b - block)
               (handfree))

  (:action pick
    :parameters (?b - block ?a - area)
    :precondition (and (in-area ?b ?a) (clear ?b) (handfree))
    :effect (and (holding ?b) (not (in-area ?b ?a)) (not (handfree))))

  (:action put-down
    :parameters (?b - block ?a - area)
    :precondition (holding ?b)
    :effect (and (in-area ?b ?a) (handfree) (not (holding ?b))))

  (:action stack
    :parameters (?b - block ?s - support)
    :precondition (and (holding ?b) (clear ?s) (not (= ?b ?s)))
    :effect (and (on ?b ?s) (handfree) (not (holding ?b)) (not (clear ?s))))

  (:action unstack
    :parameters (?b - block ?s - support)
    :precondition (and (on ?b ?s) (clear ?b) (handfree))
    :effect (and (holding ?b) (clear ?s) (not (on ?b ?s)) (not (handfree)))))
