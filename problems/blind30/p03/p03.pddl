(define (problem b30-p03) (:domain b30-pushstack)
  (:objects crate can - item crate-home dock can-home - zone)
  (:init (at crate crate-home) (at can can-home) (liftable can) (handempty))
  (:goal (and (at crate dock) (on can crate))))
