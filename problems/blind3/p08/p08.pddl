; Panda: bring a squat drum, too wide for the gripper, diagonally across the
; table into a goal region. Pick and place is cheaper but impossible.
(define (problem blind3-p08)
  (:domain blind3-arm-push)
  (:objects drum - obj
            start goal - region)
  (:init (at drum start) (handempty) (= (total-cost) 0))
  (:goal (at drum goal))
  (:metric minimize (total-cost)))
