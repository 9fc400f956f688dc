; Pushing as pushing: a planar disk slides heavy items over the surface they
; stand on. Only liftable items can be picked; the items of these problems
; are not, so every move is a quasi-static push: the disk touches one side
; face and moves into it, and the item slides without lifting. Regions on
; one surface are the only places an item can be pushed between; which face
; the disk can reach, and whether a single push can bend around a corner, is
; geometry's business.
(define (domain robust-planar-push)
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
