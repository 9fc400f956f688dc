;; A tall box close to the xArm6's base, in front and to the right, goes
;; to a spot behind the base on the left (152 deg round from the front).
(define (problem blind10-p01)
  (:domain blind10-fetch)
  (:objects post - item
            near back - spot)
  (:init (rests post near) (free-hand))
  (:goal (rests post back)))
