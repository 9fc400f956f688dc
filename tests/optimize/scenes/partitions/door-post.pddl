; door-post: carry the crate from its home region to the goal (see door-post.scene.toml).
(define (problem door-post)
  (:domain partitions)
  (:objects crate - block home goal - region)
  (:init (in crate home) (handempty))
  (:goal (in crate goal)))
