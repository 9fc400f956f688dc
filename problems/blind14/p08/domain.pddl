; blind14 p08: pushing is cheap (1), lifting costs what each item's
; lift-cost says, setting down 1 (Panda). The PDDL does not know the low
; fence across the table: the cheapest plan pushes the cube through it.
(define (domain panda-fence)
  (:requirements :strips :typing :action-costs :equality)
  (:types item zone)
  (:predicates (at ?o - item ?z - zone)
               (holding ?o - item)
               (handempty))
  (:functions (total-cost) - number
              (lift-cost ?o - item) - number)

  (:action push
    :parameters (?o - item ?from - zone ?to - zone)
    :precondition (and (at ?o ?from) (handempty) (not (= ?from ?to)))
    :effect (and (not (at ?o ?from)) (at ?o ?to)
                 (increase (total-cost) 1)))

  (:action pick
    :parameters (?o - item ?from - zone)
    :precondition (and (at ?o ?from) (handempty))
    :effect (and (not (at ?o ?from)) (not (handempty)) (holding ?o)
                 (increase (total-cost) (lift-cost ?o))))

  (:action place
    :parameters (?o - item ?to - zone)
    :precondition (holding ?o)
    :effect (and (not (holding ?o)) (handempty) (at ?o ?to)
                 (increase (total-cost) 1))))
