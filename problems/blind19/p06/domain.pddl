; blind19 p06: typed, a type hierarchy for places (spot and home under
; place), one object per place, and a goal that only asks every item to be
; stored in some spot. Which item fits which spot is the geometry's:
; nothing here says it.
(define (domain store-anywhere)
  (:requirements :strips :typing :existential-preconditions
                 :universal-preconditions)
  (:types spot home - place
          place item)
  (:predicates (at ?o - item ?p - place)
               (free ?p - place)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - item ?p - place)
    :precondition (and (at ?o ?p) (handempty))
    :effect (and (not (at ?o ?p)) (free ?p)
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?p - place)
    :precondition (and (holding ?o) (free ?p))
    :effect (and (at ?o ?p) (not (free ?p))
                 (not (holding ?o)) (handempty))))
