; blind20 p06: typed, with derived predicates (a post is occupied when an
; exhibit stands on it; used negated in `display`'s precondition) and a
; `park` move that ends the arm over a home region. Picks and displays
; undo `parked`, so the goal's `(parked)` makes the park come last.
(define (domain exhibits)
  (:requirements :strips :typing :negative-preconditions
                 :derived-predicates :existential-preconditions)
  (:types exhibit post zone)
  (:predicates (on ?o - exhibit ?p - post)
               (on-table ?o - exhibit ?z - zone)
               (occupied ?p - post)
               (holding ?o - exhibit)
               (handempty)
               (parked)
               (park-spot ?z - zone))

  (:derived (occupied ?p - post)
    (exists (?o - exhibit) (on ?o ?p)))

  (:action pick
    :parameters (?o - exhibit ?z - zone)
    :precondition (and (on-table ?o ?z) (handempty))
    :effect (and (not (on-table ?o ?z)) (not (handempty)) (holding ?o)
                 (not (parked))))

  (:action display
    :parameters (?o - exhibit ?p - post)
    :precondition (and (holding ?o) (not (occupied ?p)))
    :effect (and (on ?o ?p) (not (holding ?o)) (handempty)
                 (not (parked))))

  (:action park
    :parameters (?z - zone)
    :precondition (and (handempty) (park-spot ?z))
    :effect (parked)))
