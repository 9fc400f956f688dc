; gen1 arm-stack: a copy of domains/arm-kuka (= arm-xarm, arm-pick-place):
; pick/place take a block from/to a region, unstack/stack from/onto a block.
(define (domain gen1-arm-stack)
  (:requirements :strips :typing)
  (:types block region)
  (:predicates (at ?b - block ?r - region)
               (on ?b - block ?c - block)
               (clear ?b - block)
               (holding ?b - block)
               (handempty))

  (:action pick
    :parameters (?b - block ?from - region)
    :precondition (and (at ?b ?from) (clear ?b) (handempty))
    :effect (and (not (at ?b ?from)) (not (clear ?b)) (not (handempty))
                 (holding ?b)))

  (:action place
    :parameters (?b - block ?to - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (clear ?b) (at ?b ?to)))

  (:action unstack
    :parameters (?b - block ?from - block)
    :precondition (and (on ?b ?from) (clear ?b) (handempty))
    :effect (and (not (on ?b ?from)) (not (clear ?b)) (not (handempty))
                 (holding ?b) (clear ?from)))

  (:action stack
    :parameters (?b - block ?to - block)
    :precondition (and (holding ?b) (clear ?to))
    :effect (and (not (holding ?b)) (not (clear ?to)) (handempty) (clear ?b)
                 (on ?b ?to))))
