; blind19 p02: a drum (cylinder 9 cm across: no grasp fits) starts in a
; pocket closed to the north by a wall; it must end in `goal`, north of the
; wall, with the cube on it. The straight push drum-home -> goal runs into
; the wall, and no single push can go round it within the friction cone:
; the drum is pushed east to `corner` first, then north-west to `goal`.
; Cheapest plan (cost 4): push, pick, stack. Expected (cost 6, 4 actions):
; (push drum drum-home corner) (push drum corner goal)
; (pick cube cube-home) (stack cube drum)
(define (problem p02)
  (:domain drum-route)
  (:objects drum cube - item
            drum-home corner goal cube-home - region)
  (:init (at drum drum-home) (at cube cube-home)
         (clear drum) (clear cube) (pushable drum) (handempty)
         (= (total-cost) 0))
  (:goal (and (at drum goal) (on cube drum) (handempty)))
  (:metric minimize (total-cost)))
