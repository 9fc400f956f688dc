; Sussman's anomaly: c is on a; build the tower a-b-c.
(define (problem sussman)
  (:domain blocksworld)
  (:objects a b c - block)
  (:init (clear b) (clear c) (ontable a) (ontable b) (on c a) (handempty))
  (:goal (and (on a b) (on b c))))
