; blind23 p05: a tower of three on the table (bottom 6 cm, mid 5 cm, top
; 4 cm); only the middle piece must go to `goal`. The top must come off
; first and go somewhere (spare, goal beside mid, or back on... nothing
; else is clear until mid leaves).
; Cheapest (4) = expected: (unstack top mid) (put top spare)
;   (unstack mid bottom) (put mid goal)   [top may go to goal instead]
(define (problem p05)
  (:domain middle-of-three)
  (:objects bottom mid top - piece
            base-spot spare goal - zone)
  (:init (at bottom base-spot) (on mid bottom) (on top mid) (handempty))
  (:goal (and (at mid goal) (handempty))))
