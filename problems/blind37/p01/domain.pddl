; blind37 p01: task A (three-piece tower) as a plain four-operator blocksworld with regions.
(define (domain tower-strips)
  (:requirements :strips)
  (:predicates (block ?x) (region ?r)
               (on ?x ?y) (on-table ?x ?r)
               (clear ?x) (holding ?x) (handempty))
  (:action pick-up
    :parameters (?x ?r)
    :precondition (and (block ?x) (region ?r) (on-table ?x ?r) (clear ?x) (handempty))
    :effect (and (holding ?x) (not (on-table ?x ?r)) (not (clear ?x)) (not (handempty))))
  (:action put-down
    :parameters (?x ?r)
    :precondition (and (holding ?x) (region ?r))
    :effect (and (on-table ?x ?r) (clear ?x) (handempty) (not (holding ?x))))
  (:action unstack
    :parameters (?x ?y)
    :precondition (and (block ?x) (on ?x ?y) (clear ?x) (handempty))
    :effect (and (holding ?x) (clear ?y) (not (on ?x ?y)) (not (clear ?x)) (not (handempty))))
  (:action stack
    :parameters (?x ?y)
    :precondition (and (holding ?x) (block ?y) (clear ?y))
    :effect (and (on ?x ?y) (clear ?x) (handempty) (not (holding ?x)) (not (clear ?y)))))
