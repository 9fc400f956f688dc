; blind36 p02: blocksworld with table regions and `clear`.
(define (domain tower)
  (:requirements :strips :typing :equality)
  (:types piece region)
  (:predicates (at ?p - piece ?r - region)
               (on ?a - piece ?b - piece)
               (clear ?p - piece)
               (holding ?p - piece)
               (handempty))
  (:action pick-up
    :parameters (?p - piece ?r - region)
    :precondition (and (at ?p ?r) (clear ?p) (handempty))
    :effect (and (holding ?p) (not (at ?p ?r)) (not (clear ?p)) (not (handempty))))
  (:action put-down
    :parameters (?p - piece ?r - region)
    :precondition (holding ?p)
    :effect (and (at ?p ?r) (clear ?p) (handempty) (not (holding ?p))))
  (:action unstack
    :parameters (?a - piece ?b - piece)
    :precondition (and (on ?a ?b) (clear ?a) (handempty))
    :effect (and (holding ?a) (clear ?b) (not (on ?a ?b)) (not (clear ?a)) (not (handempty))))
  (:action stack
    :parameters (?a - piece ?b - piece)
    :precondition (and (holding ?a) (clear ?b) (not (= ?a ?b)))
    :effect (and (on ?a ?b) (clear ?a) (handempty) (not (clear ?b)) (not (holding ?a)))))
