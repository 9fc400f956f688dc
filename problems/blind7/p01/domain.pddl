;; blind7 workcell: typed parts carried between bays with action costs.
;; The gripper is either free or holding one thing; a bay takes one item
;; (a negative precondition on (occupied ?l) keeps a release out of a full
;; bay). transfer is the carry itself: from the bay over which the part was
;; grabbed to the bay it will be released in.
(define (domain blind7-workcell)
  (:requirements :strips :typing :negative-preconditions :equality :action-costs)
  (:types item location - object
          part fixture - item
          nut - part
          bay - location)
  (:predicates (in ?x - item ?l - location)
               (occupied ?l - location)
               (holding ?x - item)
               (over ?l - location)
               (gripper-free))
  (:functions (total-cost) - number)
  (:action grab
    :parameters (?x - item ?l - location)
    :precondition (and (in ?x ?l) (gripper-free))
    :effect (and (not (in ?x ?l)) (not (occupied ?l)) (not (gripper-free))
                 (holding ?x) (over ?l) (increase (total-cost) 2)))
  (:action transfer
    :parameters (?x - item ?from ?to - location)
    :precondition (and (holding ?x) (over ?from) (not (= ?from ?to)))
    :effect (and (not (over ?from)) (over ?to) (increase (total-cost) 3)))
  (:action release
    :parameters (?x - item ?l - location)
    :precondition (and (holding ?x) (over ?l) (not (occupied ?l)))
    :effect (and (not (holding ?x)) (not (over ?l)) (gripper-free)
                 (in ?x ?l) (occupied ?l) (increase (total-cost) 1))))
