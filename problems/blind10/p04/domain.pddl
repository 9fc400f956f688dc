;; blind10 p04: a disk robot nudges boxes along fixed routes between zones.
;; (route ?a ?b) says a straight nudge may go from zone a to zone b; which
;; nudges the walls and the other boxes allow is the geometry's.
(define (domain blind10-nudge)
  (:requirements :strips :typing)
  (:types box zone)
  (:predicates (inside ?b - box ?z - zone)
               (route ?from - zone ?to - zone))
  (:action nudge
    :parameters (?b - box ?from - zone ?to - zone)
    :precondition (and (inside ?b ?from) (route ?from ?to))
    :effect (and (not (inside ?b ?from)) (inside ?b ?to))))
