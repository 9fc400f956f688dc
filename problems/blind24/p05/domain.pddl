; blind24 p05: untyped planar delivery with waypoint visits. `go` is a
; `move` of the disk to a waypoint region; each waypoint must be visited
; once (`(not (visited ?w))`: a negative precondition). Unit costs.
(define (domain deliver-and-visit)
  (:requirements :strips :negative-preconditions)
  (:predicates (parcel ?o) (spot ?s) (waypoint ?w)
               (at ?o ?s) (carrying ?o) (free-hand) (visited ?w))

  (:action grab
    :parameters (?o ?s)
    :precondition (and (parcel ?o) (spot ?s) (at ?o ?s) (free-hand))
    :effect (and (carrying ?o) (not (at ?o ?s)) (not (free-hand))))

  (:action drop
    :parameters (?o ?s)
    :precondition (and (parcel ?o) (spot ?s) (carrying ?o))
    :effect (and (at ?o ?s) (free-hand) (not (carrying ?o))))

  (:action go
    :parameters (?w)
    :precondition (and (waypoint ?w) (not (visited ?w)))
    :effect (visited ?w)))
