; blind24 p02: typed blocks world on zones. Occupancy as a negative
; precondition (`(not (occupied ?z))`), `(not (= ?x ?y))` on stack; unit costs.
(define (domain reverse-tower)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types block zone)
  (:predicates (on ?x - block ?y - block)
               (at ?x - block ?z - zone)
               (occupied ?z - zone)
               (clear ?x - block)
               (holding ?x - block)
               (handempty))

  (:action pick
    :parameters (?x - block ?z - zone)
    :precondition (and (at ?x ?z) (clear ?x) (handempty))
    :effect (and (not (at ?x ?z)) (not (occupied ?z)) (not (clear ?x))
                 (not (handempty)) (holding ?x)))

  (:action place
    :parameters (?x - block ?z - zone)
    :precondition (and (holding ?x) (not (occupied ?z)))
    :effect (and (at ?x ?z) (occupied ?z) (clear ?x) (handempty)
                 (not (holding ?x))))

  (:action unstack
    :parameters (?x - block ?y - block)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (not (on ?x ?y)) (clear ?y) (not (clear ?x))
                 (not (handempty)) (holding ?x)))

  (:action stack
    :parameters (?x - block ?y - block)
    :precondition (and (holding ?x) (clear ?y) (not (= ?x ?y)))
    :effect (and (on ?x ?y) (not (clear ?y)) (clear ?x) (handempty)
                 (not (holding ?x)))))
