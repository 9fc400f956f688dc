; Station A (west end of the track) holds red in a1 and blue in a2;
; station B (east end, 1.2-1.5 m away) holds green in b1, b2 is free.
; Red must go to b1, blue to b2, green to a2: one order only
; (blue out, green in its place, red into green's).
(define (problem b28-p06)
  (:domain b28-track)
  (:objects red blue green a1 a2 b1 b2)
  (:init (part red) (part blue) (part green)
         (spot a1) (spot a2) (spot b1) (spot b2)
         (at red a1) (at blue a2) (at green b1) (free b2) (handempty))
  (:goal (and (at red b1) (at blue b2) (at green a2))))
