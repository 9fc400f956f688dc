(define (problem b31-p06) (:domain b31-towers)
  (:objects a1 a2 a3 b1 b2 b3 d1 d3 - block
            d2 - ball
            pile spare tower-a tower-b - zone)
  (:init (handempty)
         (at a1 tower-a) (on d1 a1)
         (at b1 tower-b)
         (at a2 pile) (at b2 pile) (at b3 pile) (at d2 pile) (at d3 pile)
         (on a3 d3)
         (= (total-cost) 0))
  (:goal (and (at a1 tower-a) (on a2 a1) (on a3 a2)
              (at b1 tower-b) (on b2 b1) (on b3 b2)))
  (:metric minimize (total-cost)))
