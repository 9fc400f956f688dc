; blind22 p06: typed, :action-costs, and a universally quantified goal
; (every piece seated): `seat` puts a piece into the socket made for it
; (a static `socket-for`), `put` parks it anywhere. Seating costs 2, the
; other actions 1.
(define (domain snug-sockets)
  (:requirements :strips :typing :action-costs :universal-preconditions)
  (:types socket - place
          piece place)
  (:predicates (at ?o - piece ?s - place)
               (socket-for ?o - piece ?s - socket)
               (seated ?o - piece)
               (holding ?o - piece)
               (handempty))
  (:functions (total-cost) - number)

  (:action pick
    :parameters (?o - piece ?s - place)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (seated ?o)) (not (handempty))
                 (holding ?o) (increase (total-cost) 1)))

  (:action put
    :parameters (?o - piece ?s - place)
    :precondition (holding ?o)
    :effect (and (at ?o ?s) (not (holding ?o)) (handempty)
                 (increase (total-cost) 1)))

  (:action seat
    :parameters (?o - piece ?s - socket)
    :precondition (and (holding ?o) (socket-for ?o ?s))
    :effect (and (at ?o ?s) (seated ?o) (not (holding ?o)) (handempty)
                 (increase (total-cost) 2))))
