; blind21 p05: the Panda puts a 4.5 cm cube on top of a tall stack near
; the edge of its reach: a fixed pillar (8 x 8 x 36 cm) 0.70 m out carries
; two 5 cm cubes (c1, c2); the new cube's top ends 50.5 cm above the
; table. reach (robots.md, "Reach by height"): pointing down, the Panda's
; tool reaches 0.68 m at 0.50 m up (the grasp point here: 0.49 m up,
; 0.70 m out); level or pitched side grasps reach further. The new cube
; on c2 is a tower pair (3 mm, 2 deg).
; Cheapest (2) = expected: (pick-up cube start) (stack cube c2).
(define (problem p05)
  (:domain tall-stack)
  (:objects cube c1 c2 pillar start side)
  (:init (block cube) (block c1) (block c2) (block pillar)
         (movable cube) (movable c1) (movable c2)
         (zone start) (zone side)
         (on c1 pillar) (on c2 c1) (on-zone cube start)
         (clear c2) (clear cube) (handempty))
  (:goal (on cube c2)))
