; blind22 p02: the KUKA iiwa reaches into a bin walled on three sides
; (north, south, back/east; 10 cm tall, open towards the robot) for a tin
; (box 4 x 4 x 9 cm) standing in its north-east corner: 2.5 cm from the
; north wall, 3.5 cm from the back wall. The goal only says the tin is out
; of the bin (a negative goal on a derived predicate): `mat` or `tray`.
; Fully open, the KUKA's fingers (4.0-6.0 cm from the tool's axis) meet a
; wall across either pair of faces; narrowed to the tin (5.2 cm opening,
; fingers 2.6-4.6 cm) they clear the back wall by 9 mm across the x faces.
; The goal also asks for an empty hand: without it, `(pick tin bin-floor)`
; alone (the tin held in the air) is the cheapest plan (cost 1).
; Cheapest (2) = expected (2): (pick tin bin-floor) (place tin mat|tray)
(define (problem p02)
  (:domain bin-cage)
  (:objects tin - item
            bin-floor mat tray - spot)
  (:init (at tin bin-floor) (inside bin-floor) (handempty))
  (:goal (and (not (in-bin tin)) (handempty))))
