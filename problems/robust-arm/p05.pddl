; Three cubes into a rack they fill to 91 % of its length.
(define (problem robust-arm-p05)
  (:domain robust-arm)
  (:objects a b c - block
            start rack - region)
  (:init (in a start) (in b start) (in c start) (handempty)
         (same-surface start rack) (same-surface rack start)
         (= (total-cost) 0))
  (:goal (and (in a rack) (in b rack) (in c rack)))
  (:metric minimize (total-cost)))
