; blind21 p05: the IPC blocks world's four operators, untyped, with the
; table split into zones: pick-up / put-down from and onto a zone,
; unstack / stack from and onto a block; (block ?x) and (zone ?z) are
; static type predicates. A fixed pillar is a "block" that is never clear
; of c1 and never picked (it is not (movable ?x)).
(define (domain tall-stack)
  (:requirements :strips)
  (:predicates (block ?x) (zone ?z) (movable ?x)
               (on ?x ?y) (on-zone ?x ?z) (clear ?x)
               (holding ?x) (handempty))

  (:action pick-up
    :parameters (?x ?z)
    :precondition (and (movable ?x) (zone ?z) (on-zone ?x ?z) (clear ?x)
                       (handempty))
    :effect (and (not (on-zone ?x ?z)) (not (handempty)) (holding ?x)))

  (:action put-down
    :parameters (?x ?z)
    :precondition (and (holding ?x) (zone ?z))
    :effect (and (on-zone ?x ?z) (not (holding ?x)) (handempty)))

  (:action unstack
    :parameters (?x ?y)
    :precondition (and (movable ?x) (block ?y) (on ?x ?y) (clear ?x)
                       (handempty))
    :effect (and (not (on ?x ?y)) (clear ?y) (not (handempty))
                 (holding ?x)))

  (:action stack
    :parameters (?x ?y)
    :precondition (and (holding ?x) (block ?y) (clear ?y))
    :effect (and (on ?x ?y) (not (clear ?y)) (not (holding ?x))
                 (handempty))))
