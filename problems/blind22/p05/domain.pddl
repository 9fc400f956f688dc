; blind22 p05: ADL. No action names where its object comes from: a
; `forall`/`when` effect deletes the old spot, so `pick` takes only the
; object. Nothing symbolic says that the bottle stands in the hand's way.
(define (domain approach-block)
  (:requirements :adl)
  (:types thing spot)
  (:predicates (at ?o - thing ?s - spot)
               (holding ?o - thing)
               (handempty))

  (:action pick
    :parameters (?o - thing)
    :precondition (and (handempty) (exists (?s - spot) (at ?o ?s)))
    :effect (and (forall (?s - spot) (when (at ?o ?s) (not (at ?o ?s))))
                 (holding ?o) (not (handempty))))

  (:action place
    :parameters (?o - thing ?s - spot)
    :precondition (holding ?o)
    :effect (and (at ?o ?s) (not (holding ?o)) (handempty))))
