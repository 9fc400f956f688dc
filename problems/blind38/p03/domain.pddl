; blind38 p03: a case must be carried over the scanner before it is shelved.
(define (domain scan-ship)
  (:requirements :strips :typing :negative-preconditions)
  (:types thing place)
  (:predicates (at ?o - thing ?p - place) (holding ?o - thing) (handempty)
               (scanned ?o - thing) (scanner ?p - place))
  (:action pick
    :parameters (?o - thing ?p - place)
    :precondition (and (at ?o ?p) (handempty))
    :effect (and (holding ?o) (not (at ?o ?p)) (not (handempty))))
  (:action scan
    :parameters (?o - thing ?p - place)
    :precondition (and (holding ?o) (scanner ?p) (not (scanned ?o)))
    :effect (scanned ?o))
  (:action place
    :parameters (?o - thing ?p - place)
    :precondition (and (holding ?o) (scanned ?o) (not (scanner ?p)))
    :effect (and (at ?o ?p) (handempty) (not (holding ?o)))))
