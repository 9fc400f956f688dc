; blind38 p01 (Panda): the cube goes to a small goal pad where a blocker stands. Expected 4 actions.
(define (problem p01)
  (:domain shelf-tidy)
  (:objects cube blocker - item start pad spare - region)
  (:init (handempty) (at cube start) (at blocker pad))
  (:goal (at cube pad)))
