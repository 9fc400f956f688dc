; Assembly at a jig: the base plate is seated in the jig (the jig's seat is
; a domain constant), a peg goes on the base and is fastened (a symbolic
; step, hand empty), and only a fastened peg takes the cap.
(define (domain jig-assembly)
  (:requirements :strips :typing :derived-predicates :existential-preconditions)
  (:types part zone - object
          plate peg cap - part)
  (:constants jig-seat - zone)
  (:predicates (at ?p - part ?z - zone)
               (on ?p - part ?q - part)
               (clear ?p - part)
               (holding ?p - part)
               (handempty)
               (seated ?b - plate)
               (fastened ?g - peg)
               (assembled ?b - plate))
  (:derived (assembled ?b - plate)
    (exists (?g - peg ?c - cap)
      (and (seated ?b) (on ?g ?b) (fastened ?g) (on ?c ?g))))
  (:action pick
    :parameters (?p - part ?z - zone)
    :precondition (and (at ?p ?z) (clear ?p) (handempty))
    :effect (and (not (at ?p ?z)) (not (handempty)) (holding ?p)))
  (:action seat
    :parameters (?b - plate)
    :precondition (holding ?b)
    :effect (and (not (holding ?b)) (handempty) (at ?b jig-seat) (seated ?b)))
  (:action mount-peg
    :parameters (?g - peg ?b - plate)
    :precondition (and (holding ?g) (seated ?b) (clear ?b))
    :effect (and (not (holding ?g)) (handempty) (on ?g ?b) (not (clear ?b))))
  (:action fasten
    :parameters (?g - peg ?b - plate)
    :precondition (and (on ?g ?b) (handempty))
    :effect (fastened ?g))
  (:action cap
    :parameters (?c - cap ?g - peg)
    :precondition (and (holding ?c) (fastened ?g) (clear ?g))
    :effect (and (not (holding ?c)) (handempty) (on ?c ?g) (not (clear ?g)))))
