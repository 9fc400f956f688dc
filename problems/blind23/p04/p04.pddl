; blind23 p04: a 4 cm key block from the low table into the 7 cm gap
; between two 4 cm blocks (left, right) on a stand 12 cm high; the region
; `between` is the gap less 5 mm a side. The Panda's base is at
; (0.1, -0.1), turned +90 deg (it faces +y).
; Cheapest (2) = expected: (pick key home) (place key between)
(define (problem p04)
  (:domain between-blocks)
  (:objects key left right home left-spot right-spot between spare)
  (:init (block key) (block left) (block right)
         (spot home) (spot left-spot) (spot right-spot) (spot between)
         (spot spare)
         (at key home) (at left left-spot) (at right right-spot) (free))
  (:goal (and (at key between) (at left left-spot) (at right right-spot)
              (free))))
