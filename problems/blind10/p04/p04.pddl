;; Two boxes into a dead-end corridor: box-a to the far end (deep),
;; box-b to the mouth. box-a waits in the lane in front of the corridor;
;; box-b must first be nudged into the lane, which box-a occupies, and
;; nothing symbolic says that box-a must go first.
(define (problem blind10-p04)
  (:domain blind10-nudge)
  (:objects box-a box-b - box
            lane b-home mouth deep - zone)
  (:init (inside box-a lane) (inside box-b b-home)
         (route b-home lane) (route lane mouth) (route lane deep)
         (route mouth deep))
  (:goal (and (inside box-a deep) (inside box-b mouth))))
