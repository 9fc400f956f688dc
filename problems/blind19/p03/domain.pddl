; blind19 p03: untyped STRIPS with static unary type predicates and a
; (free ?r) occupancy fact; pick and place only. Nothing here says which
; grasp family reaches the high shelf: the geometry decides.
(define (domain high-shelf)
  (:requirements :strips)
  (:predicates (item ?o) (spot ?r)
               (at ?o ?r) (free ?r) (holding ?o) (handempty))

  (:action pick
    :parameters (?o ?r)
    :precondition (and (item ?o) (spot ?r) (at ?o ?r) (handempty))
    :effect (and (not (at ?o ?r)) (free ?r)
                 (not (handempty)) (holding ?o)))

  (:action place
    :parameters (?o ?r)
    :precondition (and (item ?o) (spot ?r) (holding ?o) (free ?r))
    :effect (and (at ?o ?r) (not (free ?r))
                 (not (holding ?o)) (handempty))))
