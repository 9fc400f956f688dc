; blind19 p04: the planar disk carries an 18 cm bar from the west room to
; the east room through a 12.4 cm doorway, in which a puck stands. The
; disk (10 cm) passes with 1.2 cm a side; the bar passes only held by an
; end face, in line with the disk (held by a long side, disk and bar span
; 14 cm). The cheapest plan (2 actions) carries the bar through the puck.
; Expected (4 actions): (pick puck door) (place puck side)
; (pick bar bar-home) (place bar bar-goal)
(define (problem p04)
  (:domain doorway)
  (:objects bar puck - thing
            bar-home bar-goal door side - spot)
  (:init (at bar bar-home) (at puck door)
         (free bar-goal) (free side) (handempty))
  (:goal (at bar bar-goal)))
