; Build a on b on c, where c stands on a pedestal.
(define (problem robust-arm-p12)
  (:domain robust-arm)
  (:objects a b c - block
            top floor - region)
  (:init (in c top) (in b floor) (in a floor) (handempty)
         (= (total-cost) 0))
  (:goal (and (on a b) (on b c)))
  (:metric minimize (total-cost)))
