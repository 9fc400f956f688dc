; pillars: fetch the cargo through the 11 cm gap between two round pillars
; and bring it back. Expected: 2 actions.
(define (problem robust-pillars)
  (:domain robust-planar)
  (:objects cargo - block
            south north-goal - region)
  (:init (in cargo south) (handempty))
  (:goal (in cargo north-goal)))
