; A Panda moves blocks between regions of one table: by pick and place, or by
; pushing one over the table. Pushing costs more, so it is chosen only where
; pick and place fails geometrically.
(define (domain blind2-arm-push)
  (:requirements :strips :typing :negative-preconditions :equality :action-costs)
  (:types block region)
  (:predicates (in ?b - block ?r - region)
               (holding ?b - block)
               (handempty))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?b - block ?r - region)
    :precondition (and (in ?b ?r) (handempty))
    :effect (and (not (in ?b ?r)) (not (handempty)) (holding ?b)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?b - block ?r - region)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (in ?b ?r)
                 (increase (total-cost) 1)))

  (:action push
    :parameters (?b - block ?from - region ?to - region)
    :precondition (and (in ?b ?from) (handempty) (not (= ?from ?to)))
    :effect (and (not (in ?b ?from)) (in ?b ?to)
                 (increase (total-cost) 3))))
