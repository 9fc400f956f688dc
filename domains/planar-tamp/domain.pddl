; PDDLStream's continuous-tamp problems (caelan/pddlstream,
; examples/continuous_tamp) in tampcli's terms: a planar suction gripper over
; a bench with regions. PDDLStream samples poses inside regions and checks
; collisions with streams; here the symbolic level only says which region a
; block is in, and the trajectory optimizer finds poses that fit -- so
; whether two blocks fit, or a blocker must move first, is found out
; geometrically, by branch and bound over skeletons.
(define (domain planar-tamp)
  (:requirements :strips :typing :disjunctive-preconditions)
  (:types block region)
  (:predicates (at ?b - block ?r - region)
               (holding ?b - block)
               (handempty)
               (is-stove ?r - region)
               (cooked ?b - block))

  (:action pick
    :parameters (?b - block ?from - region)
    :precondition (and (at ?b ?from) (handempty))
    :effect (and (not (at ?b ?from)) (not (handempty)) (holding ?b)))

  (:action place
    :parameters (?b - block ?to - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (at ?b ?to)))

  ; Symbolic only: cooking happens where the block already is.
  (:action cook
    :parameters (?b - block ?r - region)
    :precondition (and (at ?b ?r) (is-stove ?r))
    :effect (cooked ?b)))
