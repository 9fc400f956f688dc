; The seed's scene: bring the box around the round obstacle into the goal
; region near (1, 1). Both push and pick + place work; push is cheaper.
(define (problem planar-push-p01)
  (:domain planar-push)
  (:objects box - item
            start goal - region
            table - surface)
  (:init (at box start) (handempty) (liftable box)
         (region-on start table) (region-on goal table)
         (= (total-cost) 0))
  (:goal (at box goal))
  (:metric minimize (total-cost)))
