; blind16 p04: swap red (spot a) and blue (spot b); the only other spot,
; c, is at the edge of the xArm's reach (0.585 m out). Expected: one
; cube to c, the other across, the first back: 6 actions.
(define (problem p04)
  (:domain xarm-swap)
  (:objects red blue a b c)
  (:init (cube red) (cube blue) (spot a) (spot b) (spot c)
         (at red a) (at blue b) (occupied a) (occupied b))
  (:goal (and (at red b) (at blue a))))
