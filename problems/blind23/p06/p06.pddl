; blind23 p06: the planar disk (r 5 cm, 10 cm across) pushes a ball
; (sphere r 3 cm) 39 cm east into `slot`, the 9 cm gap between two movable
; crates; the disk cannot follow it in, so the ball must stop at the gap's
; mouth half, the disk 1-2 cm from the crates' corners. The crates must
; stay where they are.
; Cheapest (1) = expected: (push ball slot)
(define (problem p06)
  (:domain ball-slot)
  (:objects ball crate-n crate-s - thing
            start slot n-spot s-spot park - zone)
  (:init (at ball start) (at crate-n n-spot) (at crate-s s-spot) (handempty))
  (:goal (and (at ball slot) (at crate-n n-spot) (at crate-s s-spot))))
