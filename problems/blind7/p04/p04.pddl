;; ERROR CASE (deliberate): the scene puts the block's centre at the
;; table's top face (z = 0) instead of half its height above it.
(define (problem blind7-p04)
  (:domain blind7-trays)
  (:objects gauge - tool
            tray-in tray-out - tray)
  (:init (resting gauge tray-in))
  (:goal (and (resting gauge tray-out) (not (hand-busy)))))
