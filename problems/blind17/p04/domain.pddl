; blind17 p04: typed pick / place with action costs that depend on the
; carry (KUKA iiwa). The hand remembers where the object came from,
; (holding ?o ?from), and a place costs (carry-cost ?from ?to); only the
; carries the problem links are allowed. A pick costs 1.
(define (domain relay-costs)
  (:requirements :strips :typing :action-costs)
  (:types item spot)
  (:predicates (at ?o - item ?s - spot)
               (holding ?o - item ?from - spot)
               (handempty)
               (link ?from ?to - spot))
  (:functions (total-cost) - number
              (carry-cost ?from ?to - spot) - number)

  (:action pick
    :parameters (?o - item ?s - spot)
    :precondition (and (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (not (handempty)) (holding ?o ?s)
                 (increase (total-cost) 1)))

  (:action place
    :parameters (?o - item ?from ?to - spot)
    :precondition (and (holding ?o ?from) (link ?from ?to))
    :effect (and (not (holding ?o ?from)) (handempty) (at ?o ?to)
                 (increase (total-cost) (carry-cost ?from ?to)))))
