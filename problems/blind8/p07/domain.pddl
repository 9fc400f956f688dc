;; Sorting into trays with stacking: blocksworld's four operators over
;; regions ("zones"), objects of any shape.
(define (domain blind8-sort)
  (:requirements :strips :typing)
  (:types thing zone)
  (:predicates (in ?t - thing ?z - zone)
               (on ?t - thing ?u - thing)
               (clear ?t - thing)
               (holding ?t - thing)
               (handempty))
  (:action pick
    :parameters (?t - thing ?z - zone)
    :precondition (and (in ?t ?z) (clear ?t) (handempty))
    :effect (and (not (in ?t ?z)) (not (clear ?t)) (not (handempty))
                 (holding ?t)))
  (:action place
    :parameters (?t - thing ?z - zone)
    :precondition (holding ?t)
    :effect (and (not (holding ?t)) (handempty) (clear ?t) (in ?t ?z)))
  (:action unstack
    :parameters (?t - thing ?u - thing)
    :precondition (and (on ?t ?u) (clear ?t) (handempty))
    :effect (and (not (on ?t ?u)) (not (clear ?t)) (not (handempty))
                 (holding ?t) (clear ?u)))
  (:action stack
    :parameters (?t - thing ?u - thing)
    :precondition (and (holding ?t) (clear ?u))
    :effect (and (not (holding ?t)) (not (clear ?u)) (handempty) (clear ?t)
                 (on ?t ?u))))
