; blind24 p06: a board (16 x 7 x 3 cm) must go to the dock and both cubes
; must end on it, side by side. The board cannot be lifted with a cube on
; it (`clear`), so it moves first.
; Cheapest (6) = expected (or c2 first):
;   (pick board board-home) (place board dock)
;   (pick c1 c1-home) (stack c1 board) (pick c2 c2-home) (stack c2 board)
(define (problem p06)
  (:domain shared-board)
  (:objects board - board
            c1 c2 - cube
            board-home dock c1-home c2-home - zone)
  (:init (at board board-home) (at c1 c1-home) (at c2 c2-home)
         (occupied board-home) (occupied c1-home) (occupied c2-home)
         (wide board) (handempty))
  (:goal (and (at board dock) (on c1 board) (on c2 board) (handempty))))
