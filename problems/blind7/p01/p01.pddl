;; Panda: a hexagonal nut blank (a mesh) must go into bay-b, where a can
;; stands; the can must first go to bay-c. Costs make the order matter less
;; than the negative precondition does: bay-b is occupied until the can leaves.
(define (problem blind7-p01)
  (:domain blind7-workcell)
  (:objects blank - nut
            can - fixture
            bay-a bay-b bay-c - bay)
  (:init (in blank bay-a) (occupied bay-a)
         (in can bay-b) (occupied bay-b)
         (gripper-free)
         (= (total-cost) 0))
  (:goal (and (in blank bay-b) (in can bay-c) (gripper-free)))
  (:metric minimize (total-cost)))
