; staggered: carry the crate from its home region to the goal (see staggered.scene.toml).
(define (problem staggered)
  (:domain partitions)
  (:objects crate - block home goal - region)
  (:init (in crate home) (handempty))
  (:goal (in crate goal)))
