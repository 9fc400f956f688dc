; PDDLStream's `tight`: both blocks must fit in a goal region only 2 cm
; wider and longer than the two of them side by side.
(define (problem planar-tamp-tight)
  (:domain planar-tamp)
  (:objects a b - block
            ground goal - region)
  (:init (at a ground) (at b ground) (handempty))
  (:goal (and (at a goal) (at b goal))))
