; blind17 p05: typed suction pick / place for the planar disk, where a
; pick does not name the zone it takes from: a universal conditional
; effect deletes whatever (at ?p ?z) held. The goal (in the problem) is
; negative and universal.
(define (domain evacuate)
  (:requirements :strips :typing :negative-preconditions
                 :existential-preconditions :universal-preconditions
                 :conditional-effects)
  (:types puck zone)
  (:predicates (at ?p - puck ?z - zone)
               (holding ?p - puck)
               (handempty))

  (:action pick
    :parameters (?p - puck)
    :precondition (and (handempty) (exists (?z - zone) (at ?p ?z)))
    :effect (and (holding ?p) (not (handempty))
                 (forall (?z - zone) (when (at ?p ?z) (not (at ?p ?z))))))

  (:action place
    :parameters (?p - puck ?z - zone)
    :precondition (holding ?p)
    :effect (and (not (holding ?p)) (handempty) (at ?p ?z))))
