; blind14 p08: the cube goes over the fence (pick and place, cost 5; its
; push, cost 1, runs into the fence); the can, on the far side, is pushed
; (cost 1, a pick and place would cost 5). Cheapest plan: two pushes,
; cost 2; expected: push the can, pick and place the cube, cost 6.
(define (problem p08)
  (:domain panda-fence)
  (:objects cube can - item
            cube-start cube-goal can-start can-goal - zone)
  (:init (at cube cube-start) (at can can-start) (handempty)
         (= (lift-cost cube) 4) (= (lift-cost can) 4)
         (= (total-cost) 0))
  (:goal (and (at cube cube-goal) (at can can-goal)))
  (:metric minimize (total-cost)))
