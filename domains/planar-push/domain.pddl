; The seed lesson's example (§6): a planar disk robot brings an object to a
; goal region, either by pushing it or by picking and placing it. Pushing
; slides the object over one surface, so both regions must lie on the same
; one; picking needs a liftable object. Push is the cheaper skeleton (2
; against 2 + 2), as in the seed, where the push weight is the smaller one.
(define (domain planar-push)
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
                 (increase (total-cost) 2)))

  (:action place
    :parameters (?o - item ?to - region)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 2))))
