; blind19 p01: blocks world with regions, a static tower base and a
; recursive derived predicate for "is part of the tower". Nothing here says
; which piece may stand on which: the shapes (a 5 cm cube, a 4 cm cube, a
; thin can) decide the only tower order that stands.
(define (domain tower-order)
  (:requirements :strips :typing :equality :derived-predicates
                 :existential-preconditions :universal-preconditions
                 :disjunctive-preconditions)
  (:types piece place)
  (:predicates (at ?o - piece ?r - place)
               (on ?o - piece ?u - piece)
               (clear ?o - piece)
               (free ?r - place)
               (tower-base ?r - place)
               (holding ?o - piece)
               (handempty)
               (in-tower ?o - piece))

  (:derived (in-tower ?o - piece)
    (or (exists (?r - place) (and (at ?o ?r) (tower-base ?r)))
        (exists (?u - piece) (and (on ?o ?u) (in-tower ?u)))))

  (:action pick
    :parameters (?o - piece ?r - place)
    :precondition (and (at ?o ?r) (clear ?o) (handempty))
    :effect (and (not (at ?o ?r)) (free ?r)
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - piece ?r - place)
    :precondition (and (holding ?o) (free ?r))
    :effect (and (at ?o ?r) (not (free ?r))
                 (not (holding ?o)) (handempty)))

  (:action unstack
    :parameters (?o - piece ?u - piece)
    :precondition (and (on ?o ?u) (clear ?o) (handempty))
    :effect (and (not (on ?o ?u)) (clear ?u)
                 (not (handempty)) (holding ?o)))

  (:action stack
    :parameters (?o - piece ?u - piece)
    :precondition (and (holding ?o) (clear ?u) (not (= ?o ?u)))
    :effect (and (on ?o ?u) (not (clear ?u))
                 (not (holding ?o)) (handempty))))
