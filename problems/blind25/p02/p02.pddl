; blind25 p02: the disk must park in the dock, in the east room. The only
; way east is a 20 cm corridor in which two crates stand one behind the
; other. The PDDL does not know they are in the way.
; Cheapest symbolic (1): (go dock)
; Expected (4): (pick c1 lane-w) (place c1 west-bay)
;   (push c2 lane-e east-bay) (go dock)
(define (problem p02)
  (:domain namo-dock)
  (:objects c1 c2 lane-w lane-e west-bay east-bay dock)
  (:init (crate c1) (crate c2) (bay west-bay) (bay east-bay) (dock dock)
         (at c1 lane-w) (at c2 lane-e) (handempty))
  (:goal (parked)))
