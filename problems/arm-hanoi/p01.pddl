; Three discs from the left platform to the right one: 7 moves, 14 actions.
(define (problem arm-hanoi-p01)
  (:domain arm-hanoi)
  (:objects small medium large - disc
            left middle right - platform)
  (:init (on large left) (on medium large) (on small medium)
         (clear small) (clear middle) (clear right) (handempty)
         (larger left small) (larger left medium) (larger left large)
         (larger middle small) (larger middle medium) (larger middle large)
         (larger right small) (larger right medium) (larger right large)
         (larger large medium) (larger large small) (larger medium small))
  (:goal (and (on large right) (on medium large) (on small medium))))
