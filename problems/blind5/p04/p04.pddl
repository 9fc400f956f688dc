; xArm6: a can onto a round pedestal and a thin pole into a tray region
; (both cylinders).
(define (problem blind5-p04)
  (:domain blind5-carry)
  (:objects can pole - thing
            dock pedestal_top tray - region)
  (:init (in can dock) (in pole dock) (free))
  (:goal (and (in can pedestal_top) (in pole tray))))
