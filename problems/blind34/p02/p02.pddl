; blind34 p02: a 3-cycle with exact goals (planar disk). Three things each
; stand in the next one's goal: the crate goes where the ball is, the ball
; where the puck is, the puck where the crate is. Each goal region is its
; object's footprint plus 3-4 mm (the crate's turned 30 deg: the disk never
; turns what it holds). The ball can only be pushed, the crate only carried,
; the puck either. One thing must go to `side` and come back.
; Cheapest (cost 4): each moved once: infeasible in every order (a cycle).
; Expected (cost 5): e.g. (push puck puck-spot side) (push ball ball-spot puck-spot)
;   (grab crate crate-spot) (drop crate ball-spot) (push puck side crate-spot),
;   or the ball parked in `side` instead.
(define (problem p02)
  (:domain exact-cycle)
  (:objects ball crate puck - thing
            ball-spot crate-spot puck-spot side - zone)
  (:init (at ball ball-spot) (at crate crate-spot) (at puck puck-spot)
         (pushable ball) (liftable crate) (liftable puck) (pushable puck)
         (= (total-cost) 0))
  (:goal (and (at crate ball-spot) (at ball puck-spot) (at puck crate-spot)))
  (:metric minimize (total-cost)))
