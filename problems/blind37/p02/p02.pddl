; blind37 p02: task A typed, without clear: the 6-action "move the plate with the cube on it"
; skeleton is symbolically legal and only the geometry refuses it.
; Expected 8 actions, cost 10 (grab 1, set-down 1, set-on 2).
(define (problem p02)
  (:domain tower-typed)
  (:objects plate drum cube - part
            left right park goal - area)
  (:init (gripper-free) (= (total-cost) 0)
         (resting plate left) (resting cube plate) (resting drum right))
  (:goal (and (resting plate goal) (resting drum plate) (resting cube drum)))
  (:metric minimize (total-cost)))
