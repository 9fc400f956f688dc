; blind29 p06: a battery that lasts two deliveries. Each place uses one
; charge level; a pick needs charge left (a derived predicate over a
; negated fact); recharging is a move of the empty robot into a dock
; alcove (a conditional effect drains every other level). Typed, domain
; constants, a derived predicate, :conditional-effects with :equality,
; negative preconditions.
(define (domain b29-battery)
  (:requirements :strips :typing :negative-preconditions :equality
                 :derived-predicates :conditional-effects)
  (:types item zone level)
  (:constants l0 l1 l2 - level)
  (:predicates (at ?o - item ?z - zone) (holding ?o - item) (hand-empty)
               (battery ?l - level) (next ?lo ?hi - level) (dock ?z - zone)
               (powered))

  (:derived (powered) (not (battery l0)))

  (:action pick
    :parameters (?o - item ?z - zone)
    :precondition (and (at ?o ?z) (hand-empty) (powered))
    :effect (and (not (at ?o ?z)) (holding ?o) (not (hand-empty))))

  (:action place
    :parameters (?o - item ?z - zone ?hi ?lo - level)
    :precondition (and (holding ?o) (battery ?hi) (next ?lo ?hi))
    :effect (and (at ?o ?z) (hand-empty) (not (holding ?o))
                 (not (battery ?hi)) (battery ?lo)))

  (:action recharge
    :parameters (?d - zone)
    :precondition (and (hand-empty) (dock ?d) (not (battery l2)))
    :effect (and (battery l2)
                 (forall (?l - level)
                   (when (not (= ?l l2)) (not (battery ?l)))))))
