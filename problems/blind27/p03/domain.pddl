; xArm6: blocks on blocks or pads; clear is derived.
(define (domain b27-tower)
  (:requirements :strips :typing :negative-preconditions :equality
                 :derived-predicates :existential-preconditions)
  (:types block pad - surface surface)
  (:predicates (on ?x - block ?s - surface) (holding ?x - block)
               (handempty) (clear ?s - surface))
  (:derived (clear ?s - surface)
    (and (not (exists (?b - block) (on ?b ?s)))
         (not (exists (?b - block) (and (= ?b ?s) (holding ?b))))))
  (:action lift
    :parameters (?x - block ?from - surface)
    :precondition (and (on ?x ?from) (clear ?x) (handempty))
    :effect (and (not (on ?x ?from)) (not (handempty)) (holding ?x)))
  (:action put
    :parameters (?x - block ?to - surface)
    :precondition (and (holding ?x) (clear ?to) (not (= ?x ?to)))
    :effect (and (on ?x ?to) (handempty) (not (holding ?x)))))
