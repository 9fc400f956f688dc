; blind20 p03: two crates (8 x 6 x 5 cm) must go north into their goals.
; Crate a stands 1 cm from the bench's south edge: a push north needs the
; disk's axis 4 cm beyond the edge, outside its joint limits (the bodies'
; extent), so a must be carried by suction on another face. Crate b has
; room behind it and can be pushed.
; Cheapest (cost 2): push a, push b. Expected (cost 4, 3 actions):
; (push b b-home goal-b) (pick a a-home) (place a goal-a), in either order.
(define (problem p03)
  (:domain edge-crates)
  (:objects a b - crate
            a-home b-home goal-a goal-b - zone)
  (:init (at a a-home) (at b b-home) (handempty)
         (= (total-cost) 0))
  (:goal (and (at a goal-a) (at b goal-b)))
  (:metric minimize (total-cost)))
