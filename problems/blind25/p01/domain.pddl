; blind25 p01: a tray that carries cups, written the way a researcher would
; model it symbolically: picking and placing the tray moves whatever stands
; on it (ADL: `forall`/`when` conditional effects), and the tray may be
; picked with cups on it. A cup on a tray is `at` the tray's zone.
; docs/formats.md ("Push", last paragraph) says the geometry refuses a
; grasp of an object another rests on, so the 2-action plan should be
; refused and the cups unloaded first.
(define (domain tray-ride)
  (:requirements :strips :typing :negative-preconditions
                 :conditional-effects :universal-preconditions)
  (:types tray cup - item
          item zone)
  (:predicates (at ?x - item ?z - zone)
               (on ?c - cup ?t - tray)
               (holding ?x - item)
               (handempty))

  ; the tray is lifted with its load: every cup on it leaves the zone too
  (:action pick-tray
    :parameters (?t - tray ?z - zone)
    :precondition (and (at ?t ?z) (handempty))
    :effect (and (not (at ?t ?z)) (not (handempty)) (holding ?t)
                 (forall (?c - cup) (when (on ?c ?t) (not (at ?c ?z))))))

  ; ... and set down with its load: every cup on it arrives too
  (:action place-tray
    :parameters (?t - tray ?z - zone)
    :precondition (holding ?t)
    :effect (and (at ?t ?z) (handempty) (not (holding ?t))
                 (forall (?c - cup) (when (on ?c ?t) (at ?c ?z)))))

  ; a cup standing on no tray
  (:action pick-cup
    :parameters (?c - cup ?z - zone)
    :precondition (and (at ?c ?z) (handempty)
                       (forall (?t - tray) (not (on ?c ?t))))
    :effect (and (not (at ?c ?z)) (not (handempty)) (holding ?c)))

  (:action unstack-cup
    :parameters (?c - cup ?t - tray ?z - zone)
    :precondition (and (on ?c ?t) (at ?c ?z) (handempty))
    :effect (and (not (on ?c ?t)) (not (at ?c ?z)) (not (handempty))
                 (holding ?c)))

  (:action put-cup
    :parameters (?c - cup ?z - zone)
    :precondition (holding ?c)
    :effect (and (at ?c ?z) (handempty) (not (holding ?c))))

  ; onto a tray standing in a zone (not one in the hand)
  (:action stack-cup
    :parameters (?c - cup ?t - tray ?z - zone)
    :precondition (and (holding ?c) (at ?t ?z))
    :effect (and (on ?c ?t) (at ?c ?z) (handempty) (not (holding ?c)))))
