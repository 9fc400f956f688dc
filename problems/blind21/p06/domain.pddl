; blind21 p06: ADL style. No action names where its object comes from:
; a `forall`/`when` effect deletes the old location, so `push` and `place`
; take only the target zone and `pick` only the object. Unit costs.
; Nothing symbolic says that a cube stands in the crate's way.
(define (domain kerb-push)
  (:requirements :strips :typing :negative-preconditions
                 :conditional-effects)
  (:types thing zone)
  (:predicates (at ?o - thing ?z - zone)
               (holding ?o - thing)
               (handempty))

  (:action push
    :parameters (?o - thing ?to - zone)
    :precondition (and (handempty) (not (at ?o ?to)))
    :effect (and (forall (?z - zone) (when (at ?o ?z) (not (at ?o ?z))))
                 (at ?o ?to)))

  (:action pick
    :parameters (?o - thing)
    :precondition (handempty)
    :effect (and (forall (?z - zone) (when (at ?o ?z) (not (at ?o ?z))))
                 (holding ?o) (not (handempty))))

  (:action place
    :parameters (?o - thing ?to - zone)
    :precondition (holding ?o)
    :effect (and (at ?o ?to) (not (holding ?o)) (handempty))))
