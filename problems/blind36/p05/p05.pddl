; blind36 p05 (xArm6 at the near-left corner, turned 0.5 rad): a goal the start half satisfies
; (cup already on rack-hi, block-red already in the bin) with a disjunction: the ball into the bin
; OR onto the drop area. The drop area is geometrically full (the carton stands in its middle),
; which the PDDL does not say. Expected 4: jar -> rack-lo, ball -> bin.
(define (problem p05)
  (:domain serve)
  (:objects cup jar block-red block-blue ball carton nut vial - item
            mat bin drop spare rack-lo rack-hi - region)
  (:init (handempty)
         (at cup rack-hi) (at block-red bin) (at block-blue bin) (at vial bin)
         (at ball mat) (at jar mat) (at nut mat) (at carton drop))
  (:goal (and (at cup rack-hi) (at block-red bin)
              (at jar rack-lo)
              (or (at ball bin) (at ball drop)))))
