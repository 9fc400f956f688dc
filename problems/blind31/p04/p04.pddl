(define (problem b31-p04) (:domain b31-pucks)
  (:objects p1 p2 p3 - target
            p4 p5 p6 p7 p8 - puck
            crate - crate
            west field - area
            goal-a goal-b goal-c - goal)
  (:init (handempty)
         (at p1 west) (at p2 west) (at p3 west)
         (at p4 field) (at p5 field) (at p6 field) (at p7 field) (at p8 field)
         (at crate field)
         (= (total-cost) 0))
  (:goal (and (forall (?t - target) (exists (?g - goal) (at ?t ?g)))
              (handempty)))
  (:metric minimize (total-cost)))
