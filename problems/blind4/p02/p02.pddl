; KUKA iiwa: take the target out of a corner nook to the goal. A wall stands
; 2 cm beside it on one side and a movable block 2 cm beside it on another.
(define (problem blind4-p02)
  (:domain blind4-carry)
  (:objects target block - thing
            nook goal park - region)
  (:init (in target nook) (in block nook) (free))
  (:goal (in target goal)))
