;; blind10 p03: build on supports. A piece is lifted from a zone of the
;; table or off a support (a piece or a fixed stand), and set into a zone
;; or crowned onto a support whose top is free.
(define (domain blind10-build)
  (:requirements :strips :typing)
  (:types piece stand - support
          support zone)
  (:predicates (in ?p - piece ?z - zone)
               (upon ?p - piece ?s - support)
               (free-top ?s - support)
               (carrying ?p - piece)
               (idle))
  (:action lift
    :parameters (?p - piece ?z - zone)
    :precondition (and (in ?p ?z) (free-top ?p) (idle))
    :effect (and (not (in ?p ?z)) (not (idle)) (carrying ?p)))
  (:action lift-off
    :parameters (?p - piece ?s - support)
    :precondition (and (upon ?p ?s) (free-top ?p) (idle))
    :effect (and (not (upon ?p ?s)) (not (idle)) (carrying ?p) (free-top ?s)))
  (:action settle
    :parameters (?p - piece ?z - zone)
    :precondition (carrying ?p)
    :effect (and (not (carrying ?p)) (idle) (in ?p ?z)))
  (:action crown
    :parameters (?p - piece ?s - support)
    :precondition (and (carrying ?p) (free-top ?s))
    :effect (and (not (carrying ?p)) (idle) (upon ?p ?s) (not (free-top ?s)))))
