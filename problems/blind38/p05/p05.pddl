; blind38 p05 (Panda, base turned 90 deg): swap two blocks between two spots via a buffer. Expected 6 actions.
(define (problem p05)
  (:domain swap-strips)
  (:objects red green s1 s2 buf)
  (:init (block red) (block green) (spot s1) (spot s2) (spot buf)
         (at red s1) (at green s2) (clear buf) (handempty))
  (:goal (and (at red s2) (at green s1))))
