; Two discs from the left platform to the right one: 3 moves, 6 actions.
(define (problem arm-hanoi-p02)
  (:domain arm-hanoi)
  (:objects small large - disc
            left middle right - platform)
  (:init (on large left) (on small large)
         (clear small) (clear middle) (clear right) (handempty)
         (larger left small) (larger left large)
         (larger middle small) (larger middle large)
         (larger right small) (larger right large)
         (larger large small))
  (:goal (and (on large right) (on small large))))
