; two-doors: carry the crate from its home region to the goal (see two-doors.scene.toml).
(define (problem two-doors)
  (:domain partitions)
  (:objects crate - block home goal - region)
  (:init (in crate home) (handempty))
  (:goal (in crate goal)))
