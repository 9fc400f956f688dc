; blind19 p05: the Panda fills a kit plate with six items of three shapes:
; three 4.5 cm cubes into 5.2 cm pockets (yaw within +-9.8 deg), two cans
; (r 2.5 cm) into 6 cm pockets, and a 12 x 3 cm bar, lying along y in the
; supply, into a 13 x 4 cm slot along x (turned 90 deg, +-4.8 deg).
; Expected: 12 actions (cost 12), any order, e.g.
; (pick c1 h1) (place c1 k1) (pick c2 h2) (place c2 k2) (pick c3 h3)
; (place c3 k3) (pick n1 h4) (place n1 p1) (pick n2 h5) (place n2 p2)
; (pick rod h6) (place rod slot)
(define (problem p05)
  (:domain kitting)
  (:objects c1 c2 c3 - cube
            n1 n2 - can
            rod - bar
            h1 h2 h3 h4 h5 h6 k1 k2 k3 p1 p2 slot - spot)
  (:init (at c1 h1) (at c2 h2) (at c3 h3) (at n1 h4) (at n2 h5) (at rod h6)
         (free k1) (free k2) (free k3) (free p1) (free p2) (free slot)
         (handempty))
  (:goal (and (at c1 k1) (at c2 k2) (at c3 k3)
              (at n1 p1) (at n2 p2) (at rod slot))))
