; Blocks on zones: a block is either in a zone (resting on the surface under
; it) or on another block. unstack takes a block off the one below; stack
; puts it on another. Whether a block fits a zone, and whether anything is in
; the way, is left to the geometry.
(define (domain blind6-stacks)
  (:requirements :strips :typing)
  (:types block zone)
  (:predicates (in ?b - block ?z - zone)
               (on ?b - block ?c - block)
               (clear ?b - block)
               (holding ?b - block)
               (hand-empty))
  (:action pick-up
    :parameters (?b - block ?z - zone)
    :precondition (and (in ?b ?z) (clear ?b) (hand-empty))
    :effect (and (not (in ?b ?z)) (not (clear ?b)) (not (hand-empty)) (holding ?b)))
  (:action put-down
    :parameters (?b - block ?z - zone)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (hand-empty) (clear ?b) (in ?b ?z)))
  (:action unstack
    :parameters (?b - block ?c - block)
    :precondition (and (on ?b ?c) (clear ?b) (hand-empty))
    :effect (and (not (on ?b ?c)) (not (clear ?b)) (not (hand-empty))
                 (holding ?b) (clear ?c)))
  (:action stack
    :parameters (?b - block ?c - block)
    :precondition (and (holding ?b) (clear ?c))
    :effect (and (not (holding ?b)) (not (clear ?c)) (hand-empty) (clear ?b)
                 (on ?b ?c))))
