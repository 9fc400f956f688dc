;; A QA cell: samples are inspected at a fixed station that holds one at
;; a time; a sample must be clean first, and a dirty one is wiped by
;; presenting it, held, over the wiper pad. present is a motion, wipe and
;; inspect are symbolic.
(define (domain blind9-qa-cell)
  (:requirements :strips :typing :negative-preconditions)
  (:types sample spot pad)
  (:predicates (on ?s - sample ?p - spot)
               (clear ?p - spot)
               (held ?s - sample)
               (hand-free)
               (station ?p - spot)
               (over ?s - sample ?w - pad)
               (clean ?s - sample)
               (inspected ?s - sample))
  (:action grab
    :parameters (?s - sample ?p - spot)
    :precondition (and (on ?s ?p) (hand-free))
    :effect (and (not (on ?s ?p)) (clear ?p) (not (hand-free)) (held ?s)))
  (:action put
    :parameters (?s - sample ?p - spot)
    :precondition (and (held ?s) (clear ?p))
    :effect (and (not (held ?s)) (hand-free) (on ?s ?p) (not (clear ?p))))
  (:action present
    :parameters (?s - sample ?w - pad)
    :precondition (and (held ?s) (not (clean ?s)))
    :effect (over ?s ?w))
  (:action wipe
    :parameters (?s - sample ?w - pad)
    :precondition (and (held ?s) (over ?s ?w))
    :effect (and (clean ?s) (not (over ?s ?w))))
  (:action inspect
    :parameters (?s - sample ?p - spot)
    :precondition (and (on ?s ?p) (station ?p) (clean ?s))
    :effect (inspected ?s)))
