; Stack three cubes into the tower a-b-c, c at the bottom where it stands.
; Sizes decrease upwards (5, 4.5, 4 cm) so that each cube's footprint fits
; inside the top face of the one below.
(define (problem arm-pick-place-p05)
  (:domain arm-pick-place)
  (:objects a b c - block
            start - region)
  (:init (at a start) (at b start) (at c start)
         (clear a) (clear b) (clear c) (handempty))
  (:goal (and (on a b) (on b c))))
