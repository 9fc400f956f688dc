;; blind10 p01: fetch an item from one spot and deposit it on another.
;; Nothing here says where the spots are; that is the scene's business.
(define (domain blind10-fetch)
  (:requirements :strips :typing)
  (:types item spot)
  (:predicates (rests ?i - item ?s - spot)
               (gripping ?i - item)
               (free-hand))
  (:action fetch
    :parameters (?i - item ?s - spot)
    :precondition (and (rests ?i ?s) (free-hand))
    :effect (and (not (rests ?i ?s)) (not (free-hand)) (gripping ?i)))
  (:action deposit
    :parameters (?i - item ?s - spot)
    :precondition (gripping ?i)
    :effect (and (not (gripping ?i)) (free-hand) (rests ?i ?s))))
