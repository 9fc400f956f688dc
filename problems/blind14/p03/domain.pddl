; blind14 p03: a tower of three mixed shapes (Panda): a square plate into
; the stand, a drum (cylinder) on the plate, a cube on the drum.
; Typed with a hierarchy, `either` in a parameter, and :equality.
(define (domain panda-mixed-tower)
  (:requirements :strips :typing :equality)
  (:types plate drum cube - piece
          piece area)
  (:predicates (in ?p - piece ?a - area)
               (on ?p - piece ?q - piece)
               (clear ?p - piece)
               (holding ?p - piece)
               (hand-empty))

  (:action take
    :parameters (?p - piece ?a - area)
    :precondition (and (in ?p ?a) (clear ?p) (hand-empty))
    :effect (and (holding ?p) (not (in ?p ?a)) (not (hand-empty))))

  (:action put
    :parameters (?p - piece ?a - area)
    :precondition (holding ?p)
    :effect (and (in ?p ?a) (hand-empty) (not (holding ?p))))

  (:action stack
    :parameters (?p - piece ?q - (either plate drum))
    :precondition (and (holding ?p) (clear ?q) (not (= ?p ?q)))
    :effect (and (on ?p ?q) (hand-empty) (not (holding ?p)) (not (clear ?q))))

  (:action unstack
    :parameters (?p - piece ?q - piece)
    :precondition (and (on ?p ?q) (clear ?p) (hand-empty))
    :effect (and (holding ?p) (clear ?q) (not (on ?p ?q)) (not (hand-empty)))))
