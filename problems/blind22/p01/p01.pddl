; blind22 p01: the Panda packs a brick (box 6 x 4 x 5 cm) and a can
; (cylinder r 2.4 cm, 7 cm tall) side by side into one spot, `tray`,
; 9.4 cm along x and 6.4 cm along y. The can takes 4.8 cm of the x
; length, so the brick must lie with its 4 cm side along x (yaw 90 +- ~4.9
; deg): it starts at yaw 0, its 6 cm side along x, so the grip turns it a
; quarter turn. At yaw 0 it fits the tray alone, but not beside the can.
; Cheapest (4) = expected (4), either order:
;   (pick brick brick-home) (place brick tray) (pick can can-home) (place can tray)
(define (problem p01)
  (:domain pack-pair)
  (:objects brick can brick-home can-home tray)
  (:init (item brick) (item can)
         (spot brick-home) (spot can-home) (spot tray)
         (at brick brick-home) (at can can-home))
  (:goal (and (at brick tray) (at can tray))))
