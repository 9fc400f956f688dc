; blind35 p05 (planar disk): push a crate into a dock 24 deg off its -x
; face's normal (inside the 26.6 deg friction cone); a puck stands on the way.
; Expected: puck to aside, then the push (3 actions).
(define (problem p05)
  (:domain edge-cone)
  (:objects crate puck - thing
            crate-home dock puck-home aside - zone)
  (:init (at crate crate-home) (at puck puck-home)
         (pushable crate) (liftable puck)
         (push-zone crate-home) (push-zone dock))
  (:goal (at crate dock)))
