; blind23 p05: typed blocks world on zones with a derived `clear`
; (:derived-predicates: nothing on it and not held), unit costs.
(define (domain middle-of-three)
  (:requirements :strips :typing :negative-preconditions
                 :existential-preconditions :derived-predicates)
  (:types piece zone)
  (:predicates (on ?x - piece ?y - piece)
               (at ?x - piece ?z - zone)
               (holding ?x - piece)
               (handempty)
               (clear ?x - piece))

  (:derived (clear ?x - piece)
    (and (not (holding ?x))
         (not (exists (?y - piece) (on ?y ?x)))))

  (:action pick
    :parameters (?x - piece ?z - zone)
    :precondition (and (at ?x ?z) (clear ?x) (handempty))
    :effect (and (not (at ?x ?z)) (not (handempty)) (holding ?x)))

  (:action unstack
    :parameters (?x - piece ?y - piece)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (not (on ?x ?y)) (not (handempty)) (holding ?x)))

  (:action put
    :parameters (?x - piece ?z - zone)
    :precondition (holding ?x)
    :effect (and (at ?x ?z) (not (holding ?x)) (handempty)))

  (:action stack
    :parameters (?x - piece ?y - piece)
    :precondition (and (holding ?x) (clear ?y))
    :effect (and (on ?x ?y) (not (holding ?x)) (handempty))))
