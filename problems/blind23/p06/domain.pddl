; blind23 p06: ADL (:adl): push and pick take no ?from; a forall/when
; effect deletes wherever the object was. Unit costs: a push (1) is
; cheaper than a pick and a place (2).
(define (domain ball-slot)
  (:requirements :adl)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone)
               (holding ?o - thing)
               (handempty))

  (:action push
    :parameters (?o - thing ?to - zone)
    :precondition (and (handempty) (not (at ?o ?to))
                       (exists (?z - zone) (at ?o ?z)))
    :effect (and (forall (?z - zone) (when (at ?o ?z) (not (at ?o ?z))))
                 (at ?o ?to)))

  (:action pick
    :parameters (?o - thing)
    :precondition (and (handempty) (exists (?z - zone) (at ?o ?z)))
    :effect (and (forall (?z - zone) (when (at ?o ?z) (not (at ?o ?z))))
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o - thing ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to))))
