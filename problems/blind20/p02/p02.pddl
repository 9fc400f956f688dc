; blind20 p02: the xArm6 lines up the three red cubes (4 cm) side by side
; on a narrow raised rail (region 13.6 x 4.6 cm on a 12 cm tall beam);
; a blue cube and a can stand on the table and do not matter.
; Three 4 cm cubes need 12.2 cm with the 1 mm gaps: 1.4 cm to spare along
; the rail, 6 mm across it (yaw within +-9.4 deg).
; Expected (6): pick/put each red cube onto the rail, any order.
(define (problem p02)
  (:domain rail)
  (:objects r1 r2 r3 b1 can h1 h2 h3 h4 h5 rail)
  (:init (part r1) (part r2) (part r3) (part b1) (part can)
         (red r1) (red r2) (red r3)
         (place h1) (place h2) (place h3) (place h4) (place h5) (place rail)
         (at r1 h1) (at r2 h2) (at r3 h3) (at b1 h4) (at can h5))
  (:goal (forall (?x) (imply (red ?x) (at ?x rail)))))
