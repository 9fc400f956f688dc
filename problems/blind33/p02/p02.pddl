; Planar suction regrasp: the nook shows the bar only its long south face;
; held so, disk and bar span 14 cm across the 12.4 cm door. Held by an end
; they span 10 cm. Drop it in the open and take it again by an end.
(define (problem b33-p02)
  (:domain b33-p02)
  (:objects bar - item nook stage goal - zone)
  (:init (at bar nook) (free))
  (:goal (at bar goal)))
