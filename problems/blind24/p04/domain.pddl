; blind24 p04: typed pick-and-place with a derived predicate `(binned ?c)`
; (`exists` a bin zone holding it) and a goal that only two of the four
; cans must meet (two distinct cans binned: `exists` + `=`).
(define (domain two-of-four)
  (:requirements :strips :typing :negative-preconditions :equality
                 :existential-preconditions :derived-predicates)
  (:types can zone)
  (:predicates (at ?c - can ?z - zone)
               (bin ?z - zone)
               (holding ?c - can)
               (handempty)
               (binned ?c - can))

  (:derived (binned ?c - can)
    (exists (?z - zone) (and (bin ?z) (at ?c ?z))))

  (:action pick
    :parameters (?c - can ?z - zone)
    :precondition (and (at ?c ?z) (handempty))
    :effect (and (not (at ?c ?z)) (not (handempty)) (holding ?c)))

  (:action place
    :parameters (?c - can ?z - zone)
    :precondition (holding ?c)
    :effect (and (at ?c ?z) (handempty) (not (holding ?c)))))
