; Panda: a tall thin bottle and a squat puck (both cylinders) from the
; counter to two goal regions, one of them on a raised stand.
(define (problem blind5-p03)
  (:domain blind5-carry)
  (:objects bottle puck - thing
            counter stand_top mat - region)
  (:init (in bottle counter) (in puck counter) (free))
  (:goal (and (in bottle mat) (in puck stand_top))))
