; blind24 p03: a long thin rod (28 x 2.5 x 2.5 cm) lying along x, to be laid
; along y into a 5 cm wide rack, and a 2 cm die into a 3 x 3 cm cup.
; Cheapest (4 actions, cost 2 + 1 + 1 + 1 = 5), two orders:
;   (pick rod rod-home) (place rod rack) (pick die die-home) (place die cup)
(define (problem p03)
  (:domain long-and-tiny)
  (:objects rod - rod
            die - die
            rod-home rack die-home cup - zone)
  (:init (at rod rod-home) (at die die-home) (handempty)
         (= (lift-cost rod) 2) (= (lift-cost die) 1) (= (total-cost) 0))
  (:goal (and (at rod rack) (at die cup) (handempty)))
  (:metric minimize (total-cost)))
