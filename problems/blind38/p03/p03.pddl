; blind38 p03 (xArm6): pick the case, pass it over the scan window, put it on the raised pad. Expected 3 actions.
(define (problem p03)
  (:domain scan-ship)
  (:objects case - thing intake window dock - place)
  (:init (handempty) (at case intake) (scanner window))
  (:goal (at case dock)))
