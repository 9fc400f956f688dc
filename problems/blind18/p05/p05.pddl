; blind18 p05: push a wide crate (9 cm: no gripper takes it) 30 cm along y
; into a dock between two low rails 5 mm from its sides, at the edge of the
; KUKA's reach (0.70 m out), then stack the cube on it. The cube starts in
; the dock, so the cheapest plan (push, pick, stack: cost 5) runs the crate
; into it; the cube must be taken out of the way first.
; Expected: 5 actions, cost 7:
; (pick cube dock) (place cube bin) (push crate crate-home dock)
; (pick cube bin) (stack cube crate)
(define (problem p05)
  (:domain push-and-stack)
  (:objects cube - cube
            crate - crate
            crate-home dock bin - region)
  (:init (at crate crate-home) (at cube dock) (clear crate) (handempty)
         (= (total-cost) 0))
  (:goal (and (at crate dock) (on cube crate) (handempty)))
  (:metric minimize (total-cost)))
