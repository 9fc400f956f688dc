; blind13 p04: untyped, negative preconditions (a "busy" flag instead of handempty).
(define (domain xarm-tray)
  (:requirements :strips :negative-preconditions)
  (:predicates (block ?b) (zone ?z) (in ?b ?z) (carrying ?b) (busy))

  (:action lift-block
    :parameters (?b ?z)
    :precondition (and (block ?b) (zone ?z) (in ?b ?z) (not (busy)))
    :effect (and (carrying ?b) (busy) (not (in ?b ?z))))

  (:action lower-block
    :parameters (?b ?z)
    :precondition (and (block ?b) (zone ?z) (carrying ?b))
    :effect (and (in ?b ?z) (not (carrying ?b)) (not (busy)))))
