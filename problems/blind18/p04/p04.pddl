; blind18 p04: a dead-end corridor 11.2 cm wide (the 10 cm disk has 6 mm a
; side) holds three crates in a row: a innermost (bay-1), b (bay-2), c at
; the mouth (bay-3). a must come out to the goal, and b and c go back in,
; b innermost. The cheapest plan (6 actions) takes a out first, through b
; and c; geometrically c and b must first be parked outside.
; Expected: 10 actions (cost 10), e.g.
; (pick c bay-3) (place c park-n) (pick b bay-2) (place b park-s)
; (pick a bay-1) (place a goal) (pick b park-s) (place b bay-1)
; (pick c park-n) (place c bay-2)
(define (problem p04)
  (:domain corridor)
  (:objects a b c - crate
            bay-1 bay-2 bay-3 - bay
            park-n park-s goal - park)
  (:init (at a bay-1) (at b bay-2) (at c bay-3)
         (free park-n) (free park-s) (free goal)
         (handempty))
  (:goal (and (at a goal) (at b bay-1) (at c bay-2))))
