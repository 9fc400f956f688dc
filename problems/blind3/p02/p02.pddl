; xArm6: put cube a into the bin on a small platform. A can stands in the
; bin; the domain does not say so, and the bin is too small for both.
(define (problem blind3-p02)
  (:domain blind3-pick-place)
  (:objects a can - obj
            start side bin - region)
  (:init (at a start) (at can bin) (handempty))
  (:goal (at a bin)))
