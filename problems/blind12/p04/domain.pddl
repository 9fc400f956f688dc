;; blind12 p04: spools are picked from a rack or a tray and set down on
;; one; the hand holds one spool at a time (a negated fact guards it).
(define (domain blind12-spools)
  (:requirements :strips :typing :negative-preconditions)
  (:types spool holder)
  (:predicates (on ?s - spool ?h - holder)
               (in-hand ?s - spool)
               (busy))
  (:action pick
    :parameters (?s - spool ?h - holder)
    :precondition (and (on ?s ?h) (not (busy)))
    :effect (and (in-hand ?s) (busy) (not (on ?s ?h))))
  (:action put
    :parameters (?s - spool ?h - holder)
    :precondition (in-hand ?s)
    :effect (and (on ?s ?h) (not (busy)) (not (in-hand ?s)))))
