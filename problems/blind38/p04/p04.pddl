; blind38 p04 (planar disk): the crate (not liftable) must be shoved into the dock, where a puck lies.
; Expected 3 actions: lift puck, drop it aside, shove the crate.
(define (problem p04)
  (:domain shove-lift)
  (:objects crate puck - obj home dock aside - zone)
  (:init (free) (liftable puck) (in crate home) (in puck dock) (= (total-cost) 0))
  (:goal (in crate dock))
  (:metric minimize (total-cost)))
