;; Rearranging items between spots with one hand. Nothing says how many
;; items a spot holds: that is the geometry's to decide.
(define (domain blind8-rearrange)
  (:requirements :strips :typing)
  (:types item spot)
  (:predicates (on ?i - item ?s - spot)
               (grasped ?i - item)
               (hand-free))
  (:action pick
    :parameters (?i - item ?s - spot)
    :precondition (and (on ?i ?s) (hand-free))
    :effect (and (not (on ?i ?s)) (not (hand-free)) (grasped ?i)))
  (:action put
    :parameters (?i - item ?s - spot)
    :precondition (grasped ?i)
    :effect (and (not (grasped ?i)) (hand-free) (on ?i ?s))))
