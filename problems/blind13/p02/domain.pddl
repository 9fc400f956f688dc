; blind13 p02: typed STRIPS; pick-up / put-in.
(define (domain kuka-bin)
  (:requirements :strips :typing)
  (:types cube place)
  (:predicates (on-place ?c - cube ?p - place)
               (holding ?c - cube)
               (empty-hand))

  (:action pick-up
    :parameters (?c - cube ?p - place)
    :precondition (and (on-place ?c ?p) (empty-hand))
    :effect (and (holding ?c) (not (on-place ?c ?p)) (not (empty-hand))))

  (:action put-in
    :parameters (?c - cube ?p - place)
    :precondition (holding ?c)
    :effect (and (on-place ?c ?p) (empty-hand) (not (holding ?c)))))
