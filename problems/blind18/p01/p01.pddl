; blind18 p01: stock a low cabinet shelf. A bottle and a tall box go from
; the table into two slots on the shelf, each between fixed jars, under an
; upper board 4.5 cm above their tops (no room for a top grasp's hand).
; Expected: 4 actions, cost 4, either order, e.g.
; (pick bottle bottle-home) (place bottle slot-1)
; (pick box box-home) (place box slot-2)
(define (problem p01)
  (:domain shelf-stocking)
  (:objects bottle box bottle-home box-home slot-1 slot-2)
  (:init (item bottle) (item box)
         (spot bottle-home) (spot box-home) (spot slot-1) (spot slot-2)
         (at bottle bottle-home) (at box box-home)
         (clear slot-1) (clear slot-2)
         (handempty))
  (:goal (and (at bottle slot-1) (at box slot-2) (handempty))))
