; blind37 p04: task B (three crates out of a dead-end bay, through a doorway) as plain STRIPS:
; capacity-one slots with `clear`, `handempty`.
(define (domain bay-strips)
  (:requirements :strips)
  (:predicates (crate ?c) (slot ?s) (at ?c ?s) (clear ?s) (holding ?c) (handempty))
  (:action pick
    :parameters (?c ?s)
    :precondition (and (crate ?c) (slot ?s) (at ?c ?s) (handempty))
    :effect (and (holding ?c) (clear ?s) (not (at ?c ?s)) (not (handempty))))
  (:action place
    :parameters (?c ?s)
    :precondition (and (holding ?c) (slot ?s) (clear ?s))
    :effect (and (at ?c ?s) (handempty) (not (clear ?s)) (not (holding ?c)))))
