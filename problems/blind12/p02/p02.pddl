;; A 2.5 cm bar, 9 cm long and 13 cm tall, stands in a bin 6.8 cm (centre
;; to inner face) from its 13 cm north wall; take it out to the dock.
(define (problem blind12-p02)
  (:domain blind12-binbar)
  (:objects rod bin dock)
  (:init (bar rod) (zone bin) (zone dock)
         (in rod bin) (arm-free))
  (:goal (and (in rod dock) (arm-free))))
