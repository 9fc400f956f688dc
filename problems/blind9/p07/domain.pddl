;; Crates on a bench, moved by the disk robot either way: shoved (one
;; action) or picked by suction and dragged (two). Every crate may be
;; handled both ways; which one the geometry allows is not said here.
(define (domain blind9-crates)
  (:requirements :strips :typing :equality :negative-preconditions)
  (:types crate zone)
  (:predicates (in ?c - crate ?z - zone)
               (attached ?c - crate)
               (unloaded))
  (:action shove
    :parameters (?c - crate ?from - zone ?to - zone)
    :precondition (and (in ?c ?from) (unloaded) (not (= ?from ?to)))
    :effect (and (not (in ?c ?from)) (in ?c ?to)))
  (:action latch
    :parameters (?c - crate ?from - zone)
    :precondition (and (in ?c ?from) (unloaded))
    :effect (and (not (in ?c ?from)) (not (unloaded)) (attached ?c)))
  (:action release
    :parameters (?c - crate ?to - zone)
    :precondition (attached ?c)
    :effect (and (not (attached ?c)) (unloaded) (in ?c ?to))))
