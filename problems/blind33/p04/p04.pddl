; One object to move; eight actions. The column (a mesh) stands 4 mm in
; front of part a's pocket and leaves no grip on a. The only other spot the
; column fits is a's goal: column to the goal, a to the spare, column back
; to its place, a to the goal.
(define (problem b33-p04)
  (:domain b33-p04)
  (:objects a column - item pocket front goal spare - spot)
  (:init (at a pocket) (at column front) (handempty))
  (:goal (at a goal)))
