;; blind11 p04: a slot holds goods one behind the other. A place at the
;; back of the slot can be reached (to collect from it or deposit into it)
;; only while the place in front of it, which guards it, is vacant. Every
;; place holds one good.
(define (domain blind11-slot)
  (:requirements :strips :typing)
  (:types good place)
  (:predicates (kept ?g - good ?p - place)
               (vacant ?p - place)
               (open-place ?p - place)
               (guards ?front - place ?back - place)
               (in-hand ?g - good)
               (hand-empty))
  (:action collect
    :parameters (?g - good ?p - place)
    :precondition (and (kept ?g ?p) (open-place ?p) (hand-empty))
    :effect (and (not (kept ?g ?p)) (vacant ?p) (not (hand-empty))
                 (in-hand ?g)))
  (:action collect-behind
    :parameters (?g - good ?p - place ?front - place)
    :precondition (and (kept ?g ?p) (guards ?front ?p) (vacant ?front)
                       (hand-empty))
    :effect (and (not (kept ?g ?p)) (vacant ?p) (not (hand-empty))
                 (in-hand ?g)))
  (:action deposit
    :parameters (?g - good ?p - place)
    :precondition (and (in-hand ?g) (open-place ?p) (vacant ?p))
    :effect (and (not (in-hand ?g)) (hand-empty) (kept ?g ?p)
                 (not (vacant ?p))))
  (:action deposit-behind
    :parameters (?g - good ?p - place ?front - place)
    :precondition (and (in-hand ?g) (guards ?front ?p) (vacant ?front)
                       (vacant ?p))
    :effect (and (not (in-hand ?g)) (hand-empty) (kept ?g ?p)
                 (not (vacant ?p)))))
