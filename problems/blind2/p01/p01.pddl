; A standing cylinder from one low nook to another: both are roofed 3 cm
; above its top, so it is taken and set down with the hand level.
(define (problem blind2-p01)
  (:domain blind2-nook)
  (:objects can - obj
            nook-a nook-b - region)
  (:init (in can nook-a) (handempty))
  (:goal (in can nook-b)))
