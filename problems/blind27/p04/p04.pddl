; A crate that may only be pushed plugs the one doorway of a wall; two
; boxes must be carried through it into a dock they fill; the crate must
; end in a bay 42 degrees off the push's straight line.
(define (problem b27-p04)
  (:domain b27-doorway)
  (:objects crate b1 b2 - item home1 home2 door lane crate-goal dock - zone)
  (:init (at crate door) (at b1 home1) (at b2 home2) (free)
         (liftable b1) (liftable b2) (= (total-cost) 0))
  (:goal (and (at crate crate-goal) (at b1 dock) (at b2 dock)))
  (:metric minimize (total-cost)))
