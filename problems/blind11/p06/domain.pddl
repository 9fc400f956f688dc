;; blind11 p06: a sliding robot on a bench. Heavy things are only shoved
;; (never lifted); light things are fetched and dropped. Fetching from a
;; recess needs its mouth zone clear (nothing standing in it).
(define (domain blind11-shove)
  (:requirements :strips :typing :negative-preconditions)
  (:types thing zone)
  (:predicates (in-zone ?t - thing ?z - zone)
               (clear ?z - zone)
               (light ?t - thing)
               (recess ?z - zone ?mouth - zone)
               (open-zone ?z - zone)
               (carried ?t - thing)
               (unloaded))
  (:action shove
    :parameters (?t - thing ?from - zone ?to - zone)
    :precondition (and (in-zone ?t ?from) (not (light ?t)) (clear ?to)
                       (open-zone ?to) (unloaded) (not (= ?from ?to)))
    :effect (and (not (in-zone ?t ?from)) (clear ?from) (in-zone ?t ?to)
                 (not (clear ?to))))
  (:action fetch-from-recess
    :parameters (?t - thing ?z - zone ?mouth - zone)
    :precondition (and (in-zone ?t ?z) (light ?t) (recess ?z ?mouth)
                       (clear ?mouth) (unloaded))
    :effect (and (not (in-zone ?t ?z)) (clear ?z) (not (unloaded))
                 (carried ?t)))
  (:action fetch
    :parameters (?t - thing ?z - zone)
    :precondition (and (in-zone ?t ?z) (light ?t) (open-zone ?z) (unloaded))
    :effect (and (not (in-zone ?t ?z)) (clear ?z) (not (unloaded))
                 (carried ?t)))
  (:action drop
    :parameters (?t - thing ?z - zone)
    :precondition (and (carried ?t) (clear ?z) (open-zone ?z))
    :effect (and (not (carried ?t)) (unloaded) (in-zone ?t ?z)
                 (not (clear ?z)))))
