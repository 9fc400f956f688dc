; An arm moves boxes between regions and stacks them (blocksworld's four
; operators, with regions for "the table"). Whether a box fits a region or
; on another box is left to the geometry.
(define (domain blind3-stack)
  (:requirements :strips :typing)
  (:types box region)
  (:predicates (at ?b - box ?r - region)
               (on ?b - box ?c - box)
               (clear ?b - box)
               (holding ?b - box)
               (handempty))
  (:action pick
    :parameters (?b - box ?from - region)
    :precondition (and (at ?b ?from) (clear ?b) (handempty))
    :effect (and (not (at ?b ?from)) (not (clear ?b)) (not (handempty)) (holding ?b)))
  (:action place
    :parameters (?b - box ?to - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (clear ?b) (at ?b ?to)))
  (:action unstack
    :parameters (?b - box ?from - box)
    :precondition (and (on ?b ?from) (clear ?b) (handempty))
    :effect (and (not (on ?b ?from)) (not (clear ?b)) (not (handempty))
                 (holding ?b) (clear ?from)))
  (:action stack
    :parameters (?b - box ?to - box)
    :precondition (and (holding ?b) (clear ?to))
    :effect (and (not (holding ?b)) (not (clear ?to)) (handempty) (clear ?b) (on ?b ?to))))
