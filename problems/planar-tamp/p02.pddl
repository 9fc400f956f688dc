; PDDLStream's `blocked`: block b sits in the middle of the goal region and
; leaves no room for a. The two-action skeleton is symbolically fine but
; geometrically infeasible; b must be moved out first (non-monotonic).
(define (problem planar-tamp-blocked)
  (:domain planar-tamp)
  (:objects a b - block
            ground goal - region)
  (:init (at a ground) (at b goal) (handempty))
  (:goal (at a goal)))
