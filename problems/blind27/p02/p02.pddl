; Two 4.5 cm cubes into a rimmed tray 9.6 x 5.0 cm inside, with a third cube
; (the blocker) standing in its middle.
(define (problem b27-p02)
  (:domain b27-tray)
  (:objects a b c tray home-a home-b side)
  (:init (cube a) (cube b) (cube c)
         (place tray) (place home-a) (place home-b) (place side)
         (at a home-a) (at b home-b) (at c tray) (handempty))
  (:goal (and (at a tray) (at b tray))))
