; channel: push the crate along a dead-end channel to the goal at its closed
; end; only its -x face is reachable. Expected: (push crate start goal table).
(define (problem robust-push-channel)
  (:domain robust-planar-push)
  (:objects crate - item
            start goal - region
            bench - surface)
  (:init (at crate start) (handempty)
         (region-on start bench) (region-on goal bench)
         (= (total-cost) 0))
  (:goal (at crate goal))
  (:metric minimize (total-cost)))
