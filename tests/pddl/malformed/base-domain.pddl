; A valid domain the malformed problems of this folder are checked against.
(define (domain depots)
  (:requirements :typing :action-costs :negative-preconditions)
  (:types truck - vehicle
          vehicle place cargo)
  (:constants depot - place)
  (:predicates (at ?v - vehicle ?p - place)
               (in ?c - cargo ?v - vehicle)
               (road ?from ?to - place))
  (:functions (total-cost) - number
              (distance ?from ?to - place) - number)
  (:action drive
    :parameters (?t - truck ?from ?to - place)
    :precondition (and (at ?t ?from) (road ?from ?to))
    :effect (and (not (at ?t ?from)) (at ?t ?to)
                 (increase (total-cost) (distance ?from ?to)))))
