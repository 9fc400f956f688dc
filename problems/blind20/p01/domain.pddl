; blind20 p01: typed pick / place into containers that hold one item each.
; The goal says only that every item is stored in some container; which
; item goes where is left to the geometry (the ruler fits the square case
; at no yaw; the pen fits it only along a diagonal).
(define (domain pen-case)
  (:requirements :strips :typing :existential-preconditions
                 :universal-preconditions)
  (:types item place - object
          spot container - place)
  (:predicates (at ?i - item ?p - place)
               (free ?p - place)
               (holding ?i - item)
               (handempty))

  (:action pick
    :parameters (?i - item ?p - place)
    :precondition (and (at ?i ?p) (handempty))
    :effect (and (not (at ?i ?p)) (free ?p)
                 (not (handempty)) (holding ?i)))

  (:action place
    :parameters (?i - item ?p - place)
    :precondition (and (holding ?i) (free ?p))
    :effect (and (at ?i ?p) (not (free ?p))
                 (not (holding ?i)) (handempty))))
