; blind21 p01: typed, with a type hierarchy and a domain constant: the
; turned board is `board`, a constant every problem shares, and only
; items marked (long ?i) may be laid on it (`lay` names the constant in
; its precondition, its effect and in modes.toml's `on`).
(define (domain turned-board)
  (:requirements :strips :typing)
  (:types item spot - object
          zone ledge - spot)
  (:constants board - ledge)
  (:predicates (at ?i - item ?s - spot)
               (free ?s - spot)
               (long ?i - item)
               (holding ?i - item)
               (handempty))

  (:action pick
    :parameters (?i - item ?s - spot)
    :precondition (and (at ?i ?s) (handempty))
    :effect (and (not (at ?i ?s)) (free ?s)
                 (holding ?i) (not (handempty))))

  (:action place
    :parameters (?i - item ?z - zone)
    :precondition (and (holding ?i) (free ?z))
    :effect (and (at ?i ?z) (not (free ?z))
                 (not (holding ?i)) (handempty)))

  (:action lay
    :parameters (?i - item)
    :precondition (and (holding ?i) (long ?i) (free board))
    :effect (and (at ?i board) (not (free board))
                 (not (holding ?i)) (handempty))))
