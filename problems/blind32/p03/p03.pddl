; Swap a and b between spot-1 and spot-2. The table offers no free spot:
; spot-3 holds the pedestal block c, which must stay. The only buffer is
; the top of c (or of a or b, which would bury them).
; Expected, 6 actions: (pick a spot-1) (stack a c) (pick b spot-2)
; (place b spot-1) (unstack a c) (place a spot-2)  (or b first, symmetric).
(define (problem swap-via-top)
  (:domain spots-and-stacks)
  (:objects a b c - block
            spot-1 spot-2 spot-3 - spot)
  (:init (at a spot-1) (at b spot-2) (at c spot-3)
         (clear a) (clear b) (clear c) (handempty))
  (:goal (and (at a spot-2) (at b spot-1) (at c spot-3) (handempty))))
