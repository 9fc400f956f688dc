; Panda: three different boxes from one start area to three separate goal
; regions (6 actions).
(define (problem blind5-p01)
  (:domain blind5-carry)
  (:objects a b c - thing
            start ga gb gc - region)
  (:init (in a start) (in b start) (in c start) (free))
  (:goal (and (in a ga) (in b gb) (in c gc))))
