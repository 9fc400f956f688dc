; blind25 p04: a Panda standing on a 35 cm pedestal reaches down to the
; table: a to the goal spot, b onto a, and c up onto a stand whose top is
; level with the arm's base.
; Cheapest symbolic (6) = expected (6 actions), c's pair anywhere, e.g.
;   (pick a a-home) (place a goal) (pick b b-home) (stack b a)
;   (pick c c-home) (place c stand-top)
(define (problem p04)
  (:domain pedestal-blocks)
  (:objects a b c a-home b-home c-home goal stand-top)
  (:init (block a) (block b) (block c)
         (spot a-home) (spot b-home) (spot c-home) (spot goal) (spot stand-top)
         (at a a-home) (at b b-home) (at c c-home)
         (clear a) (clear b) (clear c) (handempty))
  (:goal (and (at a goal) (on b a) (at c stand-top))))
