; blind24 p01: Sussman's anomaly (blocksworld p01's init and goal) with a
; real Panda and three equal 4.5 cm cubes: c on a, a and b on the table;
; goal a on b on c. Cheapest (6) = expected:
;   (unstack c a) (put-down c) (pick-up b) (stack b c) (pick-up a) (stack a b)
(define (problem p01)
  (:domain sussman-arm)
  (:objects a b c)
  (:init (ontable a) (ontable b) (on c a) (clear c) (clear b) (handempty))
  (:goal (and (on a b) (on b c))))
