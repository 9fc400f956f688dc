; blind14 p04: the cube into the dock. A tall vase stands beside the dock
; (only the scene says so); with a fixed wall on the dock's other side it
; leaves the hand no grip in the dock until it is moved.
(define (problem p04)
  (:domain panda-dock)
  (:objects cube vase - item
            home dock vase-spot shelf - spot)
  (:init (at cube home) (at vase vase-spot) (handempty))
  (:goal (and (at cube dock) (handempty))))
