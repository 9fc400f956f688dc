; IPC / PDDLStream "rovers" in miniature on the planar disk: navigate
; between waypoints (a move whose tool ends over the waypoint's region),
; calibrate the camera where the calibration target is visible, take an
; image (which uses the calibration up), sample a rock (suction grasp) and
; drop it on the lander's pad, and communicate the image from the lander.
; Navigation costs are path lengths in cm (via the doorway between rooms);
; the symbolic actions cost 1.
(define (domain b28-rovers)
  (:requirements :strips :typing :negative-preconditions :action-costs)
  (:types waypoint pad rock objective)
  (:predicates (rover-at ?w - waypoint) (link ?a ?b - waypoint)
               (rock-in ?r - rock ?p - pad) (near ?p - pad ?w - waypoint)
               (is-lander ?p - pad) (store-empty) (carrying ?r - rock)
               (calibrated) (cal-from ?w - waypoint)
               (visible-from ?o - objective ?w - waypoint)
               (have-image ?o - objective) (comm-from ?w - waypoint)
               (communicated ?o - objective))
  (:functions (total-cost) - number
              (path-cost ?a ?b - waypoint) - number)

  (:action navigate
    :parameters (?a ?b - waypoint)
    :precondition (and (rover-at ?a) (link ?a ?b))
    :effect (and (not (rover-at ?a)) (rover-at ?b)
                 (increase (total-cost) (path-cost ?a ?b))))

  (:action calibrate
    :parameters (?w - waypoint)
    :precondition (and (rover-at ?w) (cal-from ?w) (not (calibrated)))
    :effect (and (calibrated) (increase (total-cost) 1)))

  (:action take-image
    :parameters (?o - objective ?w - waypoint)
    :precondition (and (rover-at ?w) (visible-from ?o ?w) (calibrated))
    :effect (and (have-image ?o) (not (calibrated)) (increase (total-cost) 1)))

  (:action sample-rock
    :parameters (?r - rock ?p - pad ?w - waypoint)
    :precondition (and (rover-at ?w) (near ?p ?w) (rock-in ?r ?p) (store-empty))
    :effect (and (not (rock-in ?r ?p)) (not (store-empty)) (carrying ?r)
                 (increase (total-cost) 1)))

  (:action drop-rock
    :parameters (?r - rock ?p - pad ?w - waypoint)
    :precondition (and (carrying ?r) (rover-at ?w) (near ?p ?w) (is-lander ?p))
    :effect (and (rock-in ?r ?p) (store-empty) (not (carrying ?r))
                 (increase (total-cost) 1)))

  (:action communicate
    :parameters (?o - objective ?w - waypoint)
    :precondition (and (rover-at ?w) (comm-from ?w) (have-image ?o))
    :effect (and (communicated ?o) (increase (total-cost) 1))))
