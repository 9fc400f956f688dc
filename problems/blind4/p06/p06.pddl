; xArm6: lay a bar, lying turned 55 degrees on the table, into a slot between
; two fences on a raised platform.
(define (problem blind4-p06)
  (:domain blind4-carry)
  (:objects bar - thing
            tray slot - region)
  (:init (in bar tray) (free))
  (:goal (in bar slot)))
