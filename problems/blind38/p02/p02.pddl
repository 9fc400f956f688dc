; blind38 p02 (KUKA iiwa): Sussman's anomaly on a table with three spots. Expected 6 actions.
(define (problem p02)
  (:domain bw-regions)
  (:objects a b c - block left right middle - spot)
  (:init (handempty) (at a left) (on c a) (clear c) (at b right) (clear b))
  (:goal (and (on a b) (on b c))))
