; Ceiling-mounted Panda: untyped, STRIPS only, with static type facts.
(define (domain b26-ceiling)
  (:requirements :strips)
  (:predicates (block ?x) (region ?x) (at ?x ?r) (on ?x ?y)
               (clear ?x) (holding ?x) (handempty))

  (:action pick
    :parameters (?x ?r)
    :precondition (and (block ?x) (region ?r) (at ?x ?r) (clear ?x) (handempty))
    :effect (and (not (at ?x ?r)) (not (clear ?x)) (not (handempty))
                 (holding ?x)))

  (:action place
    :parameters (?x ?r)
    :precondition (and (holding ?x) (region ?r))
    :effect (and (not (holding ?x)) (handempty) (clear ?x) (at ?x ?r)))

  (:action stack
    :parameters (?x ?y)
    :precondition (and (holding ?x) (block ?y) (clear ?y))
    :effect (and (not (holding ?x)) (not (clear ?y)) (handempty) (clear ?x)
                 (on ?x ?y))))
