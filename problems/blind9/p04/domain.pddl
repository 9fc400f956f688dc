;; Shoving: the disk robot only pushes. Any thing may be shoved from one
;; zone into another; which zones a straight shove can reach is the
;; geometry's (the friction cone, the walls).
(define (domain blind9-shove)
  (:requirements :strips :typing :equality :negative-preconditions)
  (:types puck crate - thing
          thing zone)
  (:predicates (inside ?t - thing ?z - zone))
  (:action shove
    :parameters (?t - thing ?from - zone ?to - zone)
    :precondition (and (inside ?t ?from) (not (= ?from ?to)))
    :effect (and (not (inside ?t ?from)) (inside ?t ?to))))
