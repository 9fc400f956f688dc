; blind37 p04: crates c1 (at the bay's mouth), c2, c3 (at its back) to slots g1, g2, g3 in the
; east room. Only c1 can be reached first, then c2, then c3. Expected 6 actions.
(define (problem p04)
  (:domain bay-strips)
  (:objects c1 c2 c3 s1 s2 s3 g1 g2 g3)
  (:init (crate c1) (crate c2) (crate c3)
         (slot s1) (slot s2) (slot s3) (slot g1) (slot g2) (slot g3)
         (at c1 s1) (at c2 s2) (at c3 s3)
         (clear g1) (clear g2) (clear g3) (handempty))
  (:goal (and (at c1 g1) (at c2 g2) (at c3 g3))))
