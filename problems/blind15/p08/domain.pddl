; blind15 p08: typed stacking with conditional effects: a piece stacked on
; something grounded (the pedestal, or a piece standing on it) becomes
; grounded itself; lifting a piece ungrounds it.
(define (domain tight-stack)
  (:requirements :strips :typing :conditional-effects :equality)
  (:types piece pedestal - support support zone)
  (:predicates (at ?p - piece ?z - zone)
               (on ?p - piece ?s - support)
               (clear ?s - support)
               (grounded ?s - support)
               (holding ?p - piece)
               (handempty))

  (:action pick
    :parameters (?p - piece ?z - zone)
    :precondition (and (at ?p ?z) (clear ?p) (handempty))
    :effect (and (holding ?p) (not (at ?p ?z)) (not (handempty))))

  (:action put
    :parameters (?p - piece ?z - zone)
    :precondition (holding ?p)
    :effect (and (at ?p ?z) (handempty) (not (holding ?p))))

  (:action stack
    :parameters (?p - piece ?s - support)
    :precondition (and (holding ?p) (clear ?s) (not (= ?p ?s)))
    :effect (and (on ?p ?s) (handempty) (not (holding ?p)) (not (clear ?s))
                 (when (grounded ?s) (grounded ?p))))

  (:action unstack
    :parameters (?p - piece ?s - support)
    :precondition (and (on ?p ?s) (clear ?p) (handempty))
    :effect (and (holding ?p) (clear ?s) (not (on ?p ?s)) (not (handempty))
                 (not (grounded ?p)))))
