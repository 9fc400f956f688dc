; blind17 p06: long things go to the rack, everything else to the bin.
; The 26 cm plank lies along x on the south side of a row of 25 cm posts;
; the rack is a 5 x 30 cm strip along y on the north side, so the plank
; must be turned 90 deg (4.4 deg of play) and carried over or round the
; posts. The cube stands in the middle of the rack: symbolically either
; order works, geometrically the cube must leave first.
; Expected: 4 actions, cost 4:
; (pick cube rack) (place cube bin) (pick plank plank-home) (place plank rack)
(define (problem p06)
  (:domain sort-by-length)
  (:objects plank cube - item
            plank-home rack bin - spot)
  (:init (at plank plank-home) (at cube rack) (long plank) (handempty))
  (:goal (and (handempty)
              (forall (?o - item) (imply (long ?o) (at ?o rack)))
              (forall (?o - item) (imply (not (long ?o)) (at ?o bin))))))
