; Bring the prize home. Only the blue key opens the screen; the red key,
; nearer the robot, opens nothing.
(define (problem b29-p04)
  (:domain b29-locker)
  (:objects red-key blue-key - key
            prize - prize
            screen - door
            red-home blue-home lock-pad locker home screen-shut screen-open - zone)
  (:init (at red-key red-home) (at blue-key blue-home) (at prize locker)
         (door-at screen screen-shut) (hand-empty)
         (lock-pad lock-pad) (opens blue-key screen)
         (slides-to screen screen-open))
  (:goal (at prize home)))
