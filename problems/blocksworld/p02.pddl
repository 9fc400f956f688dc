; Four blocks: reverse the tower d-c-b-a (a on the table) into a-b-c-d.
(define (problem bw-reverse-4)
  (:domain blocksworld)
  (:objects a b c d - block)
  (:init (ontable a) (on b a) (on c b) (on d c) (clear d) (handempty))
  (:goal (and (on a b) (on b c) (on c d))))
