; blind34 p01: a blocks-world a PDDL user would write: typed, `clear`,
; negative preconditions (the hand is `busy` or not), tables are regions.
(define (domain low-hood-tower)
  (:requirements :strips :typing :negative-preconditions :equality
                 :existential-preconditions)
  (:types piece spot)
  (:predicates (on-spot ?p - piece ?s - spot)
               (on ?p - piece ?q - piece)
               (clear ?p - piece)
               (holding ?p - piece)
               (busy))
  (:action pick-up
    :parameters (?p - piece ?s - spot)
    :precondition (and (on-spot ?p ?s) (clear ?p) (not (busy)))
    :effect (and (not (on-spot ?p ?s)) (holding ?p) (busy)))
  (:action put-down
    :parameters (?p - piece ?s - spot)
    :precondition (holding ?p)
    :effect (and (on-spot ?p ?s) (not (holding ?p)) (not (busy))))
  (:action unstack
    :parameters (?p - piece ?q - piece)
    :precondition (and (on ?p ?q) (clear ?p) (not (busy)))
    :effect (and (not (on ?p ?q)) (clear ?q) (holding ?p) (busy)))
  (:action stack
    :parameters (?p - piece ?q - piece)
    :precondition (and (holding ?p) (clear ?q) (not (= ?p ?q)))
    :effect (and (on ?p ?q) (not (clear ?q)) (not (holding ?p)) (not (busy)))))
