; IPC style, untyped, :strips only: spots hold one part each (free ?s).
(define (domain b28-track)
  (:requirements :strips)
  (:predicates (part ?p) (spot ?s) (at ?p ?s) (free ?s) (holding ?p)
               (handempty))

  (:action pick
    :parameters (?p ?s)
    :precondition (and (part ?p) (spot ?s) (at ?p ?s) (handempty))
    :effect (and (holding ?p) (free ?s) (not (at ?p ?s)) (not (handempty))))

  (:action place
    :parameters (?p ?s)
    :precondition (and (holding ?p) (spot ?s) (free ?s))
    :effect (and (at ?p ?s) (handempty) (not (free ?s)) (not (holding ?p)))))
