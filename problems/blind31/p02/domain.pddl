; blind31 p02: clear a mat so that a long case can be put on it. Typed;
; action costs from a function of the object (lift-cost); a negative
; precondition (nothing heavy on the shelf). The PDDL does not say that
; the things on the mat are in the case's way: only the geometry knows.
(define (domain b31-clearmat)
  (:requirements :strips :typing :negative-preconditions :action-costs)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone) (holding ?o - item) (handempty)
               (heavy ?o - item) (high ?z - zone))
  (:functions (total-cost) - number
              (lift-cost ?o - item) - number)
  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (not (at ?o ?z)) (holding ?o) (not (handempty))
                 (increase (total-cost) (lift-cost ?o))))
  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (and (holding ?o) (not (high ?z)))
    :effect (and (at ?o ?z) (handempty) (not (holding ?o))
                 (increase (total-cost) 1)))
  (:action shelve
    :parameters (?o - item ?z - zone)
    :precondition (and (holding ?o) (high ?z) (not (heavy ?o)))
    :effect (and (at ?o ?z) (handempty) (not (holding ?o))
                 (increase (total-cost) 2))))
