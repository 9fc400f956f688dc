; blind38 p02: blocksworld with regions and clear (four operators).
(define (domain bw-regions)
  (:requirements :strips :typing)
  (:types block spot)
  (:predicates (on ?a - block ?b - block) (at ?a - block ?s - spot) (clear ?a - block)
               (holding ?a - block) (handempty))
  (:action pick
    :parameters (?a - block ?s - spot)
    :precondition (and (at ?a ?s) (clear ?a) (handempty))
    :effect (and (holding ?a) (not (at ?a ?s)) (not (clear ?a)) (not (handempty))))
  (:action put
    :parameters (?a - block ?s - spot)
    :precondition (holding ?a)
    :effect (and (at ?a ?s) (clear ?a) (handempty) (not (holding ?a))))
  (:action unstack
    :parameters (?a - block ?b - block)
    :precondition (and (on ?a ?b) (clear ?a) (handempty))
    :effect (and (holding ?a) (clear ?b) (not (on ?a ?b)) (not (clear ?a)) (not (handempty))))
  (:action stack
    :parameters (?a - block ?b - block)
    :precondition (and (holding ?a) (clear ?b))
    :effect (and (on ?a ?b) (clear ?a) (handempty) (not (clear ?b)) (not (holding ?a)))))
