; xArm6: pieces stand in regions or on each other; clear is derived
; (nothing on it and not held).
(define (domain b26-mixed-stacks)
  (:requirements :strips :typing :equality :negative-preconditions
                 :existential-preconditions :derived-predicates)
  (:types piece region)
  (:predicates (at ?p - piece ?r - region)
               (on ?p ?q - piece)
               (holding ?p - piece)
               (handempty)
               (clear ?p - piece))

  (:derived (clear ?p - piece)
    (and (not (holding ?p))
         (not (exists (?q - piece) (on ?q ?p)))))

  (:action pick
    :parameters (?p - piece ?r - region)
    :precondition (and (at ?p ?r) (clear ?p) (handempty))
    :effect (and (not (at ?p ?r)) (not (handempty)) (holding ?p)))

  (:action put
    :parameters (?p - piece ?r - region)
    :precondition (holding ?p)
    :effect (and (not (holding ?p)) (handempty) (at ?p ?r)))

  (:action unstack
    :parameters (?p ?q - piece)
    :precondition (and (on ?p ?q) (clear ?p) (handempty))
    :effect (and (not (on ?p ?q)) (not (handempty)) (holding ?p)))

  (:action stack
    :parameters (?p ?q - piece)
    :precondition (and (holding ?p) (clear ?q) (not (= ?p ?q)))
    :effect (and (not (holding ?p)) (handempty) (on ?p ?q))))
