; Five blocks in two towers (b on a; e on d on c) rebuilt as one: e-a-c-b-d.
(define (problem bw-two-towers-5)
  (:domain blocksworld)
  (:objects a b c d e - block)
  (:init (ontable a) (on b a) (clear b)
         (ontable c) (on d c) (on e d) (clear e) (handempty))
  (:goal (and (on e a) (on a c) (on c b) (on b d))))
