; Four cubes of 6, 5, 4 and 3 cm stacked into one tower on d (test only).
(define (problem tower4)
  (:domain arm-pick-place)
  (:objects a b c d - block
            start - region)
  (:init (at a start) (at b start) (at c start) (at d start)
         (clear a) (clear b) (clear c) (clear d) (handempty))
  (:goal (and (on a b) (on b c) (on c d))))
