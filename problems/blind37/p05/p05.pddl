; blind37 p05: the three crates from the bay to one large east region. Expected 6 actions, cost 9.
(define (problem p05)
  (:domain bay-typed)
  (:objects c1 c2 c3 - crate bay east - zone)
  (:init (idle) (= (total-cost) 0) (in c1 bay) (in c2 bay) (in c3 bay))
  (:goal (and (in c1 east) (in c2 east) (in c3 east)))
  (:metric minimize (total-cost)))
