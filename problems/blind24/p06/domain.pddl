; blind24 p06: typed blocks world with boards that hold several items.
; `clear` is derived (`forall`: nothing on it, not held); a stack needs
; the support clear unless it is a board (`or`: a disjunctive
; precondition); a zone holds one thing (`(not (occupied ?z))`).
(define (domain shared-board)
  (:requirements :strips :typing :negative-preconditions :equality
                 :disjunctive-preconditions :universal-preconditions
                 :derived-predicates)
  (:types board cube - item item zone)
  (:predicates (at ?x - item ?z - zone)
               (on ?x - item ?y - item)
               (occupied ?z - zone)
               (holding ?x - item)
               (handempty)
               (wide ?x - item)
               (clear ?x - item))

  (:derived (clear ?x - item)
    (and (not (holding ?x))
         (forall (?y - item) (not (on ?y ?x)))))

  (:action pick
    :parameters (?x - item ?z - zone)
    :precondition (and (at ?x ?z) (clear ?x) (handempty))
    :effect (and (not (at ?x ?z)) (not (occupied ?z)) (not (handempty))
                 (holding ?x)))

  (:action place
    :parameters (?x - item ?z - zone)
    :precondition (and (holding ?x) (not (occupied ?z)))
    :effect (and (at ?x ?z) (occupied ?z) (handempty) (not (holding ?x))))

  (:action unstack
    :parameters (?x - cube ?y - item)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (not (on ?x ?y)) (not (handempty)) (holding ?x)))

  (:action stack
    :parameters (?x - cube ?y - item)
    :precondition (and (holding ?x) (not (= ?x ?y))
                       (or (wide ?y) (clear ?y)))
    :effect (and (on ?x ?y) (handempty) (not (holding ?x)))))
