; blind16 p05: typed pick / place (Panda) with a derived predicate:
; an item is done when it is in its own target area.
(define (domain panda-contact)
  (:requirements :strips :typing :derived-predicates
                 :existential-preconditions)
  (:types item area)
  (:predicates (at ?o - item ?a - area)
               (target ?o - item ?a - area)
               (done ?o - item)
               (holding ?o - item)
               (handempty))

  (:derived (done ?o - item)
    (exists (?a - area) (and (target ?o ?a) (at ?o ?a))))

  (:action pick
    :parameters (?o - item ?a - area)
    :precondition (and (at ?o ?a) (handempty))
    :effect (and (not (at ?o ?a)) (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - item ?a - area)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?a))))
