; blind38 p05: untyped STRIPS with capacity-one spots (clear).
(define (domain swap-strips)
  (:requirements :strips)
  (:predicates (block ?b) (spot ?s) (at ?b ?s) (clear ?s) (holding ?b) (handempty))
  (:action pick
    :parameters (?b ?s)
    :precondition (and (block ?b) (spot ?s) (at ?b ?s) (handempty))
    :effect (and (holding ?b) (clear ?s) (not (at ?b ?s)) (not (handempty))))
  (:action place
    :parameters (?b ?s)
    :precondition (and (holding ?b) (spot ?s) (clear ?s))
    :effect (and (at ?b ?s) (handempty) (not (clear ?s)) (not (holding ?b)))))
