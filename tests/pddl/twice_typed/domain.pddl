; A depot in the style of IPC storage: `bay` is declared under `object` and
; again under `surface` (a crate rests on a surface), which Fast Downward
; reads as a subtype of both.
(define (domain twice-typed)
  (:requirements :typing)
  (:types crane surface room bay - object
          stock dock - bay
          bay crate - surface)
  (:predicates (free ?s - stock)
               (inside ?x - (either stock crate) ?r - room)
               (idle ?c - crane)
               (holding ?c - crane ?x - crate)
               (at ?c - crane ?b - bay)
               (on ?x - crate ?s - surface)
               (next ?a ?b - bay))
  (:action pick
    :parameters (?c - crane ?x - crate ?s - stock ?b - bay ?r - room)
    :precondition (and (next ?s ?b) (at ?c ?b) (idle ?c) (on ?x ?s) (inside ?s ?r))
    :effect (and (not (on ?x ?s)) (free ?s) (not (idle ?c)) (holding ?c ?x)
                 (not (inside ?x ?r))))
  (:action put
    :parameters (?c - crane ?x - crate ?s - stock ?b - bay ?r - room)
    :precondition (and (next ?s ?b) (at ?c ?b) (holding ?c ?x) (free ?s) (inside ?s ?r))
    :effect (and (not (holding ?c ?x)) (idle ?c) (not (free ?s)) (on ?x ?s)
                 (inside ?x ?r)))
  (:action move
    :parameters (?c - crane ?from ?to - bay)
    :precondition (and (at ?c ?from) (next ?from ?to))
    :effect (and (not (at ?c ?from)) (at ?c ?to))))
