; Two parts stand in narrow rail channels with a crate wedged between them,
; 5 mm from each: no grip reaches either part until the crate is pushed
; out of the row. Nothing in the PDDL says so.
(define (problem b28-p04)
  (:domain b28-singulate)
  (:objects p1 p2 - part crate - crate
            p1-home p2-home crate-home aside goal1 goal2 - zone)
  (:init (at p1 p1-home) (at p2 p2-home) (at crate crate-home) (hand-free)
         (liftable p1) (liftable p2) (pushable crate) (= (total-cost) 0))
  (:goal (and (at p1 goal1) (at p2 goal2)))
  (:metric minimize (total-cost)))
