; A planar disk slides crates over a bench. Only liftable crates can be
; picked; the crates here are not, so every move is a quasi-static push. The
; symbolic level knows which region a crate is in and which surface a region
; lies on; whether a region has room for a crate is geometry's business.
(define (domain blind2-push)
  (:requirements :strips :typing :action-costs)
  (:types item region surface)
  (:predicates (at ?o - item ?r - region)
               (holding ?o - item)
               (handempty)
               (liftable ?o - item)
               (region-on ?r - region ?s - surface))
  (:functions (total-cost) - number)

  (:action push
    :parameters (?o - item ?from - region ?to - region ?s - surface)
    :precondition (and (at ?o ?from) (handempty)
                       (region-on ?from ?s) (region-on ?to ?s))
    :effect (and (not (at ?o ?from)) (at ?o ?to)
                 (increase (total-cost) 2)))

  (:action pick
    :parameters (?o - item ?from - region)
    :precondition (and (at ?o ?from) (handempty) (liftable ?o))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - item ?to - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 1))))
