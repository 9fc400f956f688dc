; blind20 p05: typed pick / place with a type hierarchy and one item per
; spot. Nothing says that the front cube of a two-deep channel leaves no
; room for the fingers round the back cube.
(define (domain channel)
  (:requirements :strips :typing)
  (:types cube spot - object
          rack-spot table-spot - spot)
  (:predicates (at ?c - cube ?s - spot)
               (free ?s - spot)
               (holding ?c - cube)
               (handempty))

  (:action pick
    :parameters (?c - cube ?s - spot)
    :precondition (and (at ?c ?s) (handempty))
    :effect (and (not (at ?c ?s)) (free ?s)
                 (not (handempty)) (holding ?c)))

  (:action place
    :parameters (?c - cube ?s - table-spot)
    :precondition (and (holding ?c) (free ?s))
    :effect (and (at ?c ?s) (not (free ?s))
                 (not (holding ?c)) (handempty))))
