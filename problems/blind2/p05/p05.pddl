; Pack three blocks of different sizes into one square region: a long bar
; and two squares of different depths, 86 % of the region's area.
(define (problem blind2-p05)
  (:domain blind2-planar)
  (:objects bar sq10 sq8 - block
            supply pack - region)
  (:init (in bar supply) (in sq10 supply) (in sq8 supply) (handempty))
  (:goal (and (in bar pack) (in sq10 pack) (in sq8 pack))))
