; blind17 p03: restore the scene. The part must go to the goal tray,
; and the tall block beside it must end where it started: that goal
; holds at the start, but the block (5 mm from the part's east face,
; a fixed wall 5 mm from its north face) leaves no grip on the part.
; The cheapest skeleton, (pick part part-home) (place part goal), is
; meant to fail; expected answer, 6 actions, cost 6:
; (pick block block-home) (place block spare) (pick part part-home)
; (place part goal) (pick block spare) (place block block-home)
(define (problem p03)
  (:domain restore-scene)
  (:objects part block - item
            part-home block-home spare goal - spot)
  (:init (at part part-home) (at block block-home)
         (free spare) (free goal) (handempty))
  (:goal (and (at part goal) (at block block-home))))
