; blind21 p03: typed STRIPS for the planar disk: carry pucks one at a time
; between zones, one puck per zone (`empty`). Nothing symbolic says that a
; puck left in front of the door shuts the door.
(define (domain door-pucks)
  (:requirements :strips :typing)
  (:types puck zone)
  (:predicates (at ?p - puck ?z - zone)
               (empty ?z - zone)
               (carrying ?p - puck)
               (free-hand))

  (:action pick
    :parameters (?p - puck ?z - zone)
    :precondition (and (at ?p ?z) (free-hand))
    :effect (and (not (at ?p ?z)) (empty ?z)
                 (carrying ?p) (not (free-hand))))

  (:action drop
    :parameters (?p - puck ?z - zone)
    :precondition (and (carrying ?p) (empty ?z))
    :effect (and (at ?p ?z) (not (empty ?z))
                 (not (carrying ?p)) (free-hand))))
