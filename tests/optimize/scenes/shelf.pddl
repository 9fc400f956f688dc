; A bar from under a low shelf to a mat (tests/optimize/test_grasps.py).
(define (problem shelf)
  (:domain robust-arm)
  (:objects a - block
            under-shelf mat - region)
  (:init (in a under-shelf) (handempty)
         (same-surface under-shelf mat) (same-surface mat under-shelf)
         (= (total-cost) 0))
  (:goal (in a mat))
  (:metric minimize (total-cost)))
