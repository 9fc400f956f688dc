; blind16 p06: carry a cube and a 15 cm bottle from the -y side of a
; 40 cm tall wall to the +y side, over it or round its inner end.
; Expected: 4 actions, cost 6.
(define (problem p06)
  (:domain kuka-wall)
  (:objects cube bottle - item
            cube-home bottle-home cube-goal bottle-goal - area)
  (:init (at cube cube-home) (at bottle bottle-home) (handempty)
         (= (total-cost) 0))
  (:goal (and (at cube cube-goal) (at bottle bottle-goal)))
  (:metric minimize (total-cost)))
