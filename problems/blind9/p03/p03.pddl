;; KUKA iiwa mounted turned 90 deg: a 15.4 cm bar lying at 61 deg must be
;; seated in a slot region 16.6 x 4.5 cm along y (yaw 90 deg within about
;; 4 deg) on a raised fixture.
(define (problem blind9-p03)
  (:domain blind9-fixture)
  (:objects bar-1 - bar
            rack slot - location)
  (:init (lies bar-1 rack) (idle))
  (:goal (lies bar-1 slot)))
