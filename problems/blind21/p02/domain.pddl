; blind21 p02: typed, the place's spot typed `(either shelf-spot
; table-spot)`, one item per spot with a negative precondition
; `(not (occupied ?s))`. Nothing says that half the goal region lies
; under a hood.
(define (domain wafer)
  (:requirements :strips :typing :negative-preconditions)
  (:types wafer shelf-spot table-spot)
  (:predicates (at ?w - wafer ?s - (either shelf-spot table-spot))
               (occupied ?s - (either shelf-spot table-spot))
               (holding ?w - wafer)
               (handempty))

  (:action pick
    :parameters (?w - wafer ?s - (either shelf-spot table-spot))
    :precondition (and (at ?w ?s) (handempty))
    :effect (and (not (at ?w ?s)) (not (occupied ?s))
                 (holding ?w) (not (handempty))))

  (:action place
    :parameters (?w - wafer ?s - (either shelf-spot table-spot))
    :precondition (and (holding ?w) (not (occupied ?s)))
    :effect (and (at ?w ?s) (occupied ?s)
                 (not (holding ?w)) (handempty))))
