; PDDLStream's `tight`: both blocks must fit in a goal region they fill to
; 80 % of its length (4 cm to spare along x, 2 cm across).
(define (problem planar-tamp-tight)
  (:domain planar-tamp)
  (:objects a b - block
            ground goal - region)
  (:init (at a ground) (at b ground) (handempty))
  (:goal (and (at a goal) (at b goal))))
