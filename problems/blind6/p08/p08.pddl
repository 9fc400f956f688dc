; Panda: two boxes to two zones. The tin fits the gripper; the case is
; 7.5 cm across its narrowest side, which looks like it fits the Panda's
; 7.8 cm opening, but solve takes at most 7.3 cm (the 5 mm slack), and the
; domain has no push: unsolvable.
(define (problem blind6-p08)
  (:domain blind6-carry)
  (:objects tin case - part
            shelf-zone left right - zone)
  (:init (in tin shelf-zone) (in case shelf-zone) (hand-empty))
  (:goal (and (in tin left) (in case right))))
