;; Retrieval from a cluttered spot: the gripper is busy while it holds
;; something; nothing symbolic says what is in whose way.
(define (domain blind8-retrieve)
  (:requirements :strips :typing :negative-preconditions)
  (:types piece - object
          bottle gem - piece
          spot)
  (:predicates (at ?p - piece ?s - spot)
               (gripping ?p - piece)
               (busy))
  (:action lift
    :parameters (?p - piece ?s - spot)
    :precondition (and (at ?p ?s) (not (busy)))
    :effect (and (not (at ?p ?s)) (busy) (gripping ?p)))
  (:action lower
    :parameters (?p - piece ?s - spot)
    :precondition (gripping ?p)
    :effect (and (not (gripping ?p)) (not (busy)) (at ?p ?s))))
