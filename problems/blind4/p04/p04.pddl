; Planar disk, push only: slide a wide crate into a walled bay whose mouth
; leaves 1.7 cm a side. The robot starts on the far side of the bay.
(define (problem blind4-p04)
  (:domain blind4-slide)
  (:objects crate - heavy
            yard apron bay - region)
  (:init (in crate yard))
  (:goal (in crate bay)))
