; Loading a dish rack: plates stand on edge; each goes into an empty slot
; between the rack's tines.
(define (domain dish-rack)
  (:requirements :strips :typing)
  (:types plate place - object
          slot spot - place)
  (:predicates (at ?p - plate ?l - place)
               (vacant ?l - place)
               (holding ?p - plate)
               (handempty))
  (:action take
    :parameters (?p - plate ?from - place)
    :precondition (and (at ?p ?from) (handempty))
    :effect (and (not (at ?p ?from)) (vacant ?from) (not (handempty)) (holding ?p)))
  (:action load
    :parameters (?p - plate ?s - slot)
    :precondition (and (holding ?p) (vacant ?s))
    :effect (and (not (holding ?p)) (handempty) (at ?p ?s) (not (vacant ?s)))))
