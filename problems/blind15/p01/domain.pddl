; blind15 p01: typed pick and place on a cluttered counter (Panda).
(define (domain counter-clutter)
  (:requirements :strips :typing)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone)
               (holding ?o - item)
               (handempty))

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (handempty))
    :effect (and (holding ?o) (not (at ?o ?z)) (not (handempty))))

  (:action place
    :parameters (?o - item ?z - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?z) (handempty) (not (holding ?o)))))
