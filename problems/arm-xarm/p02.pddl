; Stack cube a (4 cm) on cube b (5 cm), which stays where it stands.
(define (problem arm-xarm-p02)
  (:domain arm-xarm)
  (:objects a b - block
            start - region)
  (:init (at a start) (at b start) (clear a) (clear b) (handempty))
  (:goal (on a b)))
