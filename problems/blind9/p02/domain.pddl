;; Capping: a lid is lifted from a zone and pressed onto an open jar's
;; top (a place onto another movable body). Jars themselves are never
;; handled.
(define (domain blind9-capping)
  (:requirements :strips :typing)
  (:types lid jar zone)
  (:predicates (lid-at ?l - lid ?z - zone)
               (lid-held ?l - lid)
               (gripper-empty)
               (open ?j - jar)
               (capped ?j - jar ?l - lid))
  (:action lift-lid
    :parameters (?l - lid ?z - zone)
    :precondition (and (lid-at ?l ?z) (gripper-empty))
    :effect (and (not (lid-at ?l ?z)) (not (gripper-empty)) (lid-held ?l)))
  (:action cap
    :parameters (?l - lid ?j - jar)
    :precondition (and (lid-held ?l) (open ?j))
    :effect (and (not (lid-held ?l)) (gripper-empty)
                 (not (open ?j)) (capped ?j ?l))))
