; Either goal region will do. Both skeletons cost 2 symbolically; the near
; region is the cheaper trajectory, so branch and bound keeps it and prunes
; or rejects the far one.
(define (problem planar-tamp-dual)
  (:domain planar-tamp)
  (:objects a - block
            ground near far - region)
  (:init (at a ground) (handempty))
  (:goal (or (at a near) (at a far))))
