; Panda, push only: slide a square tile, too wide to grasp and turned 35
; degrees, 24 cm along its own face normal into the goal, past a tall post.
(define (problem blind4-p07)
  (:domain blind4-slide)
  (:objects tile - heavy
            dock goal - region)
  (:init (in tile dock))
  (:goal (in tile goal)))
