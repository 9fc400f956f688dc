; Two boxes into one pad that has a fixed round pillar in its middle.
(define (problem b26-p04)
  (:domain b26-pillar-pad)
  (:objects a b - item home-a home-b pad - region)
  (:init (at a home-a) (at b home-b) (handempty) (liftable a) (liftable b)
         (= (total-cost) 0))
  (:goal (and (at a pad) (at b pad)))
  (:metric minimize (total-cost)))
