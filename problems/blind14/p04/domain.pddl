; blind14 p04: put a cube into a dock (Panda). The PDDL knows nothing of
; what stands beside the dock: any item may go to any spot.
(define (domain panda-dock)
  (:requirements :strips :typing)
  (:types item spot)
  (:predicates (at ?i - item ?s - spot)
               (holding ?i - item)
               (handempty))

  (:action pick
    :parameters (?i - item ?s - spot)
    :precondition (and (at ?i ?s) (handempty))
    :effect (and (holding ?i) (not (at ?i ?s)) (not (handempty))))

  (:action place
    :parameters (?i - item ?s - spot)
    :precondition (holding ?i)
    :effect (and (at ?i ?s) (handempty) (not (holding ?i)))))
