; blind29 p03: a SCARA arm kits three toys of three shapes (a mesh duck, a
; ball, a can) into a tote on the far side of a ceiling column its links
; cannot sweep through. Typed, a derived predicate (exists), a universally
; quantified goal, a negative precondition.
(define (domain b29-scara-kit)
  (:requirements :strips :typing :negative-preconditions :derived-predicates
                 :existential-preconditions :universal-preconditions)
  (:types toy place)
  (:predicates (at ?t - toy ?p - place) (holding ?t - toy) (hand-empty)
               (kit-place ?p - place) (kitted ?t - toy))

  (:derived (kitted ?t - toy)
    (exists (?p - place) (and (kit-place ?p) (at ?t ?p))))

  (:action pick
    :parameters (?t - toy ?p - place)
    :precondition (and (at ?t ?p) (hand-empty))
    :effect (and (not (at ?t ?p)) (holding ?t) (not (hand-empty))))

  (:action place
    :parameters (?t - toy ?p - place)
    :precondition (and (holding ?t) (not (kitted ?t)))
    :effect (and (at ?t ?p) (hand-empty) (not (holding ?t)))))
