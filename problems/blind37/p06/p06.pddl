; blind37 p06: the crates east, each carry through the doorway as a move over the `door` region.
; Expected 11 actions: 3 x (grab, go-east, drop) with 2 go-west between.
(define (problem p06)
  (:domain bay-move)
  (:objects c1 c2 c3 - crate bay east - area door - doorway)
  (:init (in c1 bay) (in c2 bay) (in c3 bay) (west-area bay) (east-area east))
  (:goal (forall (?c - crate) (delivered ?c))))
