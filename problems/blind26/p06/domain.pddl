; xArm6: a part must be carried over a scanner pad (a move of the loaded
; hand) before it may be placed in an outbound tray; other zones take it
; unscanned. Typed, negative and disjunctive preconditions.
(define (domain b26-scanner)
  (:requirements :strips :typing :negative-preconditions
                 :disjunctive-preconditions)
  (:types part zone)
  (:predicates (at ?p - part ?z - zone) (holding ?p - part) (handempty)
               (scanned ?p - part) (outbound ?z - zone) (scanner ?z - zone))

  (:action pick
    :parameters (?p - part ?z - zone)
    :precondition (and (at ?p ?z) (handempty))
    :effect (and (not (at ?p ?z)) (not (handempty)) (holding ?p)))

  (:action scan
    :parameters (?p - part ?z - zone)
    :precondition (and (holding ?p) (scanner ?z) (not (scanned ?p)))
    :effect (scanned ?p))

  (:action place
    :parameters (?p - part ?z - zone)
    :precondition (and (holding ?p) (not (scanner ?z))
                       (or (scanned ?p) (not (outbound ?z))))
    :effect (and (not (holding ?p)) (handempty) (at ?p ?z))))
