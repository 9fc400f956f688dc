; blind20 p04: the planar disk carries an 18 x 4 cm bar (along x; the disk
; never turns it) from the west room through an L-shaped corridor: leg 1
; runs east, 18 cm wide; leg 2 runs north, 22 cm wide, to the goal at its
; end. Held by a long side the disk and bar span 14 cm across leg 1 and
; 18 cm across leg 2 (both pass); held end-on they span 4 / 10 cm across
; leg 1 but 28 cm across leg 2 (no way round the corner).
; Expected (2): (pick bar bar-home) (place bar goal), a long-side grip.
(define (problem p04)
  (:domain l-corridor)
  (:objects bar - thing
            bar-home goal - spot)
  (:init (at bar bar-home) (occupied bar-home) (handempty))
  (:goal (at bar goal)))
