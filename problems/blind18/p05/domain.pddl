; blind18 p05: typed, with action costs: pushing the crate costs 3, each
; pick, place and stack 1. Only cubes can be picked (the crate is also too
; wide for the gripper); a crate is pushed only with nothing on it and the
; hand empty.
(define (domain push-and-stack)
  (:requirements :strips :typing :equality :negative-preconditions
                 :action-costs)
  (:types cube crate - thing
          thing region)
  (:predicates (at ?t - thing ?r - region)
               (on ?o - cube ?c - crate)
               (clear ?c - crate)
               (holding ?o - cube)
               (handempty))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?o - cube ?r - region)
    :precondition (and (at ?o ?r) (handempty))
    :effect (and (not (at ?o ?r)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - cube ?r - region)
    :precondition (holding ?o)
    :effect (and (at ?o ?r) (not (holding ?o)) (handempty)
                 (increase (total-cost) 1)))

  (:action stack
    :parameters (?o - cube ?c - crate)
    :precondition (and (holding ?o) (clear ?c))
    :effect (and (on ?o ?c) (not (clear ?c)) (not (holding ?o)) (handempty)
                 (increase (total-cost) 1)))

  (:action push
    :parameters (?c - crate ?from ?to - region)
    :precondition (and (at ?c ?from) (clear ?c) (handempty)
                       (not (= ?from ?to)))
    :effect (and (not (at ?c ?from)) (at ?c ?to)
                 (increase (total-cost) 3))))
