; blind34 p04: a kit of four mixed parts (box, cylinder, sphere, mesh) onto a
; fixture turned 35 deg (xArm6), whose spots are taken at the start. The bar
; and the mesh nut go onto plates turned with the fixture and barely larger
; than them, so each must be set down turned to the fixture's yaw (bar from
; -20 deg to 35 +- 2 deg, the nut from 0 to 35 +- 5 deg); the pin onto the
; middle plate; the ball into the cup (a goal given as a region only).
; But the pin stands in the cup and the ball on the nut's plate: the order
; pin, then ball, then nut is forced (or a park on a spare spot).
; Expected (8): (pick pin cup) (place pin plate-b) (pick ball plate-c)
;   (place ball cup) (pick nut nut-home) (place nut plate-c), and the bar's
;   pair anywhere in that sequence.
(define (problem p04)
  (:domain turned-kit)
  (:objects bar pin ball nut - item
            bar-home nut-home spare-a spare-b plate-a plate-b plate-c cup - loc)
  (:init (at bar bar-home) (at pin cup) (at ball plate-c)
         (at nut nut-home) (handempty))
  (:goal (and (at bar plate-a) (at pin plate-b) (at nut plate-c) (at ball cup))))
