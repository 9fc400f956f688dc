; blind15 p02: untyped, static type predicates, a conditional effect:
; an item put down in a zone under the shelf is "stored".
(define (domain kuka-shelf)
  (:requirements :strips :conditional-effects)
  (:predicates (item ?o) (zone ?z) (shelf ?z)
               (at ?o ?z) (stored ?o) (holding ?o) (free))

  (:action take
    :parameters (?o ?z)
    :precondition (and (item ?o) (zone ?z) (at ?o ?z) (free))
    :effect (and (holding ?o) (not (at ?o ?z)) (not (free)) (not (stored ?o))))

  (:action put
    :parameters (?o ?z)
    :precondition (and (item ?o) (zone ?z) (holding ?o))
    :effect (and (at ?o ?z) (free) (not (holding ?o))
                 (when (shelf ?z) (stored ?o)))))
