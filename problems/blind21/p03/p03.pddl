; blind21 p03: planar disk (r 5 cm). A wall across the bench (y = 0, running
; to both edges) has one door 16 cm wide in its middle. Three pucks
; (cylinders r 3 cm) start in the south room; each has a goal in the north
; room: p1 west, p2 east, p3 in `g-door`, right in front of the door on the
; north side. Once p3 stands there the disk cannot pass the door any more
; (g-door is 8 x 8 cm: the puck's centre within 1 cm of the door's axis,
; 5-7 cm north of the wall; the disk, 10 cm across, passes the 16 cm door
; only with its axis within 3 cm of the door's axis, and then meets the puck), so p3 must come last.
; Cheapest (6): any order of the three carries; 4 of the 6 orders put p3
; before another puck and are infeasible.
; Expected (6): p1 and p2 first (either order), then
;   (pick p3 h3) (drop p3 g-door).
(define (problem p03)
  (:domain door-pucks)
  (:objects p1 p2 p3 - puck
            h1 h2 h3 g-west g-east g-door - zone)
  (:init (at p1 h1) (at p2 h2) (at p3 h3)
         (empty g-west) (empty g-east) (empty g-door)
         (free-hand))
  (:goal (and (at p1 g-west) (at p2 g-east) (at p3 g-door))))
