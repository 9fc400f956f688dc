; blind25 p02: navigation among movable obstacles for the planar disk.
; Untyped, with static type predicates. Crates may be carried (suction) or
; pushed into a bay; `go` parks the disk over a dock (a `move` with a
; target). Every action but `go` unparks the disk, so `go` comes last.
; The PDDL does not say which crate is in the way of which motion.
(define (domain namo-dock)
  (:requirements :strips :negative-preconditions :equality)
  (:predicates (crate ?o) (bay ?z) (dock ?z)
               (at ?o ?z) (holding ?o) (handempty) (parked))

  (:action pick
    :parameters (?o ?z)
    :precondition (and (crate ?o) (at ?o ?z) (handempty))
    :effect (and (holding ?o) (not (at ?o ?z)) (not (handempty))
                 (not (parked))))

  (:action place
    :parameters (?o ?z)
    :precondition (and (crate ?o) (bay ?z) (holding ?o))
    :effect (and (at ?o ?z) (handempty) (not (holding ?o)) (not (parked))))

  (:action push
    :parameters (?o ?from ?to)
    :precondition (and (crate ?o) (bay ?to) (at ?o ?from) (handempty)
                       (not (= ?from ?to)))
    :effect (and (at ?o ?to) (not (at ?o ?from)) (not (parked))))

  (:action go
    :parameters (?z)
    :precondition (and (dock ?z) (handempty) (not (parked)))
    :effect (parked)))
