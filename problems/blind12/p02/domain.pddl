;; blind12 p02: untyped; what may be lifted and where things may go are
;; static predicates of the problem.
(define (domain blind12-binbar)
  (:requirements :strips)
  (:predicates (bar ?b) (zone ?z)
               (in ?b ?z)
               (lifted ?b)
               (arm-free))
  (:action lift
    :parameters (?b ?z)
    :precondition (and (bar ?b) (zone ?z) (in ?b ?z) (arm-free))
    :effect (and (lifted ?b) (not (in ?b ?z)) (not (arm-free))))
  (:action lower
    :parameters (?b ?z)
    :precondition (and (bar ?b) (zone ?z) (lifted ?b))
    :effect (and (in ?b ?z) (arm-free) (not (lifted ?b)))))
