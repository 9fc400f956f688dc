; blind29 p05: a seesaw. A plank lies balanced on a narrow fulcrum; a bar
; fixed over the fulcrum keeps weights off the plank's middle. The heavy
; weight must end on the plank, which tips (the stacking rule's centre of
; mass, with masses from the scene) unless a counterweight, which the goal
; does not mention, is loaded on the other arm first. Typed, an existential
; goal, separate actions for the plank (load / unload) and for the zones.
(define (domain b29-seesaw)
  (:requirements :strips :typing :existential-preconditions)
  (:types weight board zone)
  (:predicates (at ?w - weight ?z - zone) (on-board ?w - weight ?b - board)
               (holding ?w - weight) (hand-empty))

  (:action pick
    :parameters (?w - weight ?z - zone)
    :precondition (and (at ?w ?z) (hand-empty))
    :effect (and (not (at ?w ?z)) (holding ?w) (not (hand-empty))))

  (:action unload
    :parameters (?w - weight ?b - board)
    :precondition (and (on-board ?w ?b) (hand-empty))
    :effect (and (not (on-board ?w ?b)) (holding ?w) (not (hand-empty))))

  (:action place
    :parameters (?w - weight ?z - zone)
    :precondition (holding ?w)
    :effect (and (at ?w ?z) (hand-empty) (not (holding ?w))))

  (:action load
    :parameters (?w - weight ?b - board)
    :precondition (holding ?w)
    :effect (and (on-board ?w ?b) (hand-empty) (not (holding ?w)))))
