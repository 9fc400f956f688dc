; blind22 p04: the xArm6 must move a slab (box 6 x 6 x 4 cm) from dock-a
; to dock-b, but a cap (cylinder r 2 cm, 5 cm tall) stands on it: unstack
; the cap first, then move the bottom piece. The goal lets the cap end
; either back on the slab or in `spare` (a disjunction).
; Cheapest (4) = expected (4):
;   (unstack cap slab) (put cap spare) (pick slab dock-a) (put slab dock-b)
; (the cap back on the slab costs 6: it must be parked and taken again.)
(define (problem p04)
  (:domain cap-slab)
  (:objects slab cap - piece
            dock-a dock-b spare - zone)
  (:init (at slab dock-a) (on cap slab) (clear cap) (handempty))
  (:goal (and (at slab dock-b)
              (or (on cap slab) (at cap spare)))))
