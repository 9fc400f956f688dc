; A block from under a roof on a ledge into a tray on the table, turned.
(define (problem robust-arm-p08)
  (:domain robust-arm)
  (:objects a - block
            cubby tray - region)
  (:init (in a cubby) (handempty)
         (= (total-cost) 0))
  (:goal (in a tray))
  (:metric minimize (total-cost)))
