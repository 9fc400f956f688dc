; doorway: fetch a through an 11 cm doorway (5 mm a side for the disk) and
; bring it back through. Expected: 2 actions.
(define (problem robust-doorway)
  (:domain robust-planar)
  (:objects a - block
            east west-goal - region)
  (:init (in a east) (handempty))
  (:goal (in a west-goal)))
