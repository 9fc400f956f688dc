; blind34 p06: three mixed items (a box turned 40 deg, a ball, a mesh nut)
; into four rimmed trays, one item a tray. Costs say the three near trays
; (1 each) are cheapest, the far one dearest (3). By footprint the small
; tray takes the ball or the nut, but its 4 cm rims stand where the fingers
; must go (a local failure, no proof; the region's edges on the rims'
; inner faces leave the ball no play at all); the long tray takes only the
; box. So one item must go to the far tray.
; Cheapest (cost 6): trays near, long, small: infeasible (the small tray's rims).
; Expected (cost 8, 6 actions): box -> long, ball and nut -> near and far.
(define (problem p06)
  (:domain tray-sort)
  (:objects brick ball nut - item
            brick-home ball-home nut-home - spot
            t-near t-long t-small t-far - tray)
  (:init (at brick brick-home) (at ball ball-home) (at nut nut-home)
         (handempty)
         (= (tray-cost t-near) 1) (= (tray-cost t-long) 1)
         (= (tray-cost t-small) 1) (= (tray-cost t-far) 3)
         (= (total-cost) 0))
  (:goal (forall (?o - item) (stored ?o)))
  (:metric minimize (total-cost)))
