; blind34 p04: kitting. Plain typed pick/place; a location is a region or a
; fixture plate (a fixed body named in the problem); nothing says which
; item fits where.
(define (domain turned-kit)
  (:requirements :strips :typing)
  (:types item loc)
  (:predicates (at ?o - item ?l - loc)
               (holding ?o - item)
               (handempty))
  (:action pick
    :parameters (?o - item ?l - loc)
    :precondition (and (at ?o ?l) (handempty))
    :effect (and (not (at ?o ?l)) (not (handempty)) (holding ?o)))
  (:action place
    :parameters (?o - item ?l - loc)
    :precondition (holding ?o)
    :effect (and (at ?o ?l) (handempty) (not (holding ?o)))))
