; blind25 p03: six items in a row (three colours, boxes and cylinders) must
; each go into the bin of its colour; two items a bin.
; Cheapest symbolic (12) = expected (12 actions), six pick/place pairs in an
; order left to the search (720 orders), e.g.
;   (pick g1 row) (place g1 green-bin) (pick r1 row) (place r1 red-bin)
;   (pick b1 row) (place b1 blue-bin) (pick g2 row) (place g2 green-bin)
;   (pick b2 row) (place b2 blue-bin) (pick r2 row) (place r2 red-bin)
(define (problem p03)
  (:domain planar-sort)
  (:objects g1 r1 b1 g2 b2 r2 - item
            row red-bin green-bin blue-bin - zone
            red green blue - colour)
  (:init (at g1 row) (at r1 row) (at b1 row) (at g2 row) (at b2 row) (at r2 row)
         (colour-of r1 red) (colour-of r2 red)
         (colour-of g1 green) (colour-of g2 green)
         (colour-of b1 blue) (colour-of b2 blue)
         (takes red-bin red) (takes green-bin green) (takes blue-bin blue)
         (handempty))
  (:goal (and (forall (?o - item) (sorted ?o)) (handempty))))
