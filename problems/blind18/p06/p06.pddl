; blind18 p06: swap a cube and a can between two cages of four 12 cm posts
; through a spare spot. The Panda's hand (6.3 cm thick) fits between a
; cage's posts (7.2 cm apart, surface to surface) only along the cage's
; axes, 3 mm a side, within about 2.5 deg of yaw; cage-b is turned 30 deg,
; so the cube must be turned to 30 deg on the way (its 7 x 7 cm region
; leaves it 0.85 mm of play at that yaw).
; Expected: 6 actions, cost 6, e.g.
; (pick can cage-b) (place can spare) (pick cube cage-a)
; (place cube cage-b) (pick can spare) (place can cage-a)
(define (problem p06)
  (:domain cage-swap)
  (:objects cube can - item
            cage-a cage-b spare - spot)
  (:init (in cube cage-a) (in can cage-b) (handempty))
  (:goal (and (in cube cage-b) (in can cage-a) (handempty))))
