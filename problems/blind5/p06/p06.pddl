; Panda: a heavy crate, too wide for the gripper either way, must be pushed
; 22 cm away from the robot, past a tall bottle standing beside its path.
(define (problem blind5-p06)
  (:domain blind5-shove)
  (:objects crate - crate
            near far - region)
  (:init (in crate near) (free) (= (total-cost) 0))
  (:goal (in crate far))
  (:metric minimize (total-cost)))
