; Planar disk, push only: bring the crate round a wall into the goal.
(define (problem blind3-p04)
  (:domain blind3-push)
  (:objects crate - item
            start east north-east goal - region)
  (:init (at crate start))
  (:goal (at crate goal)))
