; blind20 p03: planar disk, push or carry, with action costs (a push costs
; 1, a pick 2 and a place 1: pushing is the cheap way). Nothing says that a
; crate at the bench's edge leaves the disk no room behind it.
(define (domain edge-crates)
  (:requirements :strips :typing :equality :action-costs)
  (:types crate zone)
  (:predicates (at ?c - crate ?z - zone)
               (holding ?c - crate)
               (handempty))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?c - crate ?from ?to - zone)
    :precondition (and (at ?c ?from) (handempty) (not (= ?from ?to)))
    :effect (and (not (at ?c ?from)) (at ?c ?to)
                 (increase (total-cost) 1)))

  (:action pick
    :parameters (?c - crate ?z - zone)
    :precondition (and (at ?c ?z) (handempty))
    :effect (and (not (at ?c ?z)) (not (handempty)) (holding ?c)
                 (increase (total-cost) 2)))

  (:action place
    :parameters (?c - crate ?z - zone)
    :precondition (holding ?c)
    :effect (and (at ?c ?z) (not (holding ?c)) (handempty)
                 (increase (total-cost) 1))))
