; blind35 p06 (planar disk): push a crate into a dock 30 deg off its -x
; face's normal (outside every face's 26.6 deg cone); a puck stands on the way.
; Expected: unsolvable, proved before any skeleton (the cone rule).
(define (problem p06)
  (:domain edge-cone)
  (:objects crate puck - thing
            crate-home dock puck-home aside - zone)
  (:init (at crate crate-home) (at puck puck-home)
         (pushable crate) (liftable puck)
         (push-zone crate-home) (push-zone dock))
  (:goal (at crate dock)))
