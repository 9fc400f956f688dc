;; Restocking: a container is fetched from wherever it stands and stowed
;; on a spot. Nothing symbolic says which spot is high or far: that is
;; the geometry's business.
(define (domain blind9-restock)
  (:requirements :strips :typing)
  (:types container spot)
  (:predicates (stands ?c - container ?s - spot)
               (in-hand ?c - container)
               (hand-free))
  (:action fetch
    :parameters (?c - container ?from - spot)
    :precondition (and (stands ?c ?from) (hand-free))
    :effect (and (not (stands ?c ?from)) (not (hand-free)) (in-hand ?c)))
  (:action stow
    :parameters (?c - container ?to - spot)
    :precondition (in-hand ?c)
    :effect (and (not (in-hand ?c)) (hand-free) (stands ?c ?to))))
