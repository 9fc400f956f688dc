; A block from under a roof on a ledge to a tray (tests/optimize/test_grasps.py).
(define (problem ledge)
  (:domain robust-arm)
  (:objects a - block
            cubby tray - region)
  (:init (in a cubby) (handempty)
         (= (total-cost) 0))
  (:goal (in a tray))
  (:metric minimize (total-cost)))
