; blind34 p06: sorting into capacity-one trays, written as a PDDL user
; would: typed, negative preconditions (a tray is not `full`), a universally
; quantified goal, and action costs (a tray's cost is how far it is).
(define (domain tray-sort)
  (:requirements :strips :typing :negative-preconditions
                 :universal-preconditions :action-costs)
  (:types item spot tray)
  (:predicates (at ?o - item ?s - spot)
               (in ?o - item ?t - tray)
               (stored ?o - item)
               (full ?t - tray)
               (holding ?o - item)
               (handempty))
  (:functions (total-cost) - number
              (tray-cost ?t - tray) - number)
  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (handempty)) (holding ?o)
                 (increase (total-cost) 1)))
  (:action drop-in
    :parameters (?o - item ?t - tray)
    :precondition (and (holding ?o) (not (full ?t)))
    :effect (and (in ?o ?t) (stored ?o) (full ?t) (handempty)
                 (not (holding ?o)) (increase (total-cost) (tray-cost ?t)))))
