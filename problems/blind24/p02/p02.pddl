; blind24 p02: reverse a tower of four equal 4 cm cubes (blocksworld p02
; with a real xArm6): a on b on c on d in spot-a; goal d on c on b on a,
; a in spot-b. Cheapest (8) = expected:
;   (unstack a b) (place a spot-b) (unstack b c) (stack b a)
;   (unstack c d) (stack c b) (pick d spot-a) (stack d c)
(define (problem p02)
  (:domain reverse-tower)
  (:objects a b c d - block
            spot-a spot-b spare - zone)
  (:init (on a b) (on b c) (on c d) (at d spot-a) (occupied spot-a)
         (clear a) (handempty))
  (:goal (and (on d c) (on c b) (on b a) (at a spot-b) (handempty))))
