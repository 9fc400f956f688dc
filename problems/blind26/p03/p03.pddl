; A cube stands on a box, a can on a drum. Swap the tops: the can
; (cylinder) onto the box, the cube (box) onto the drum (cylinder).
(define (problem b26-p03)
  (:domain b26-mixed-stacks)
  (:objects block drum cube can - piece west east side - region)
  (:init (at block west) (at drum east) (on cube block) (on can drum)
         (handempty))
  (:goal (and (on can block) (on cube drum))))
