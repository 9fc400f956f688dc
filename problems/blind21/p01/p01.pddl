; blind21 p01: the Panda lays a 13 x 3 x 4 cm bar along a narrow board
; (16 x 4.6 x 1 cm, a fixed body turned 35 deg on the table) and puts a
; ball (sphere, r 2.5 cm) into a goal region.
; The bar fits the board only along it: the footprint window is about
; +-7.2 deg about 35 deg (or 215 deg), and since the bar's circle (13.3 cm)
; is wider than the board, the tower rule holds it within 2 deg of the
; board's faces and 3 mm of its centre.
; Expected (4): (pick bar bar-home) (lay bar) (pick ball ball-home)
;               (place ball goal-ball), the two pairs in either order.
(define (problem p01)
  (:domain turned-board)
  (:objects bar ball - item
            bar-home ball-home goal-ball - zone)
  (:init (at bar bar-home) (at ball ball-home)
         (free goal-ball) (free board)
         (long bar) (handempty))
  (:goal (and (at bar board) (at ball goal-ball))))
