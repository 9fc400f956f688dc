; blind18 p02: a 2 x 3 grid of slots (10 cm pitch) holds five cubes and one
; gap (s6). The goal rotates the five cubes one slot round the cycle
; s1 -> s2 -> s3 -> s4 -> s5 -> s1 and leaves s6 empty again, so one cube
; must wait in s6 while the other four move up: 6 moves, 12 actions.
; Expected (one of the five cheapest, cost 12), e.g.
; (pick c5 s5) (place c5 s6) (pick c4 s4) (place c4 s5) (pick c3 s3)
; (place c3 s4) (pick c2 s2) (place c2 s3) (pick c1 s1) (place c1 s2)
; (pick c5 s6) (place c5 s1)
(define (problem p02)
  (:domain grid-rearrange)
  (:objects c1 c2 c3 c4 c5 - cube
            s1 s2 s3 s4 s5 s6 - slot)
  (:init (in c1 s1) (in c2 s2) (in c3 s3) (in c4 s4) (in c5 s5)
         (occupied s1) (occupied s2) (occupied s3) (occupied s4)
         (occupied s5)
         (handempty))
  (:goal (and (in c1 s2) (in c2 s3) (in c3 s4) (in c4 s5) (in c5 s1)
              (not (occupied s6)) (handempty))))
