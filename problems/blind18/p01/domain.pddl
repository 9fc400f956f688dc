; blind18 p01: untyped STRIPS (static unary type predicates), the
; library's textbook pick / place with a (clear ?s) occupancy fact.
(define (domain shelf-stocking)
  (:requirements :strips)
  (:predicates (item ?o) (spot ?s)
               (at ?o ?s) (clear ?s)
               (holding ?o) (handempty))

  (:action pick
    :parameters (?o ?s)
    :precondition (and (item ?o) (spot ?s) (at ?o ?s) (handempty))
    :effect (and (not (at ?o ?s)) (clear ?s)
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o ?s)
    :precondition (and (item ?o) (spot ?s) (holding ?o) (clear ?s))
    :effect (and (at ?o ?s) (not (clear ?s))
                 (not (holding ?o)) (handempty))))
