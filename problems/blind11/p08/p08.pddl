;; Three parts on three pads, each to move one pad on round the ring:
;; gear from pad-a to pad-b, nut from pad-b to pad-c, cup from pad-c to
;; pad-a. One spare pad. A cyclic exchange: four moves, eight actions.
(define (problem blind11-p08)
  (:domain blind11-rotate)
  (:objects gear nut cup - part
            pad-a pad-b pad-c spare - pad)
  (:init (occupies gear pad-a) (occupies nut pad-b) (occupies cup pad-c)
         (empty spare) (gripper-open))
  (:goal (and (occupies gear pad-b) (occupies nut pad-c)
              (occupies cup pad-a) (gripper-open))))
