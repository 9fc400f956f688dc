(define (problem p03)
  (:domain xarm-slot)
  (:objects can - can
            bench slot - zone)
  (:init (stands can bench) (gripper-free) (= (total-cost) 0))
  (:goal (stands can slot))
  (:metric minimize (total-cost)))
