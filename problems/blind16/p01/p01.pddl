; blind16 p01: the crate (9 cm, too wide to grip, not liftable) must be
; pushed 24 cm along +y into crate-goal; the cube goes where the crate
; stood. The PDDL does not say the crate is in the cube's way: the order
; (push first) is the geometry's. Expected: push, pick, place (3).
(define (problem p01)
  (:domain kuka-push-then-pick)
  (:objects crate cube - thing
            crate-home crate-goal cube-home - zone)
  (:init (at crate crate-home) (at cube cube-home) (handempty)
         (liftable cube) (pushable crate))
  (:goal (and (at crate crate-goal) (at cube crate-home))))
