; blind36 p06 (Panda at the far end, turned 180 deg): swap the jar (on the mat) and the cup
; (on the rack's upper level); mat, rack-hi and spare hold one thing each. Parking in a spot
; costs 1, in a store (bin, drop, rack-lo) 3. Expected 6 actions, cost 6, via spare.
(define (problem p06)
  (:domain swap-costs)
  (:objects cup jar block-red block-blue ball carton nut vial - item
            mat rack-hi spare - spot
            bin drop rack-lo - store)
  (:init (handempty) (= (total-cost) 0)
         (at jar mat) (at cup rack-hi) (free spare)
         (at nut rack-lo) (at carton drop)
         (at ball bin) (at block-red bin) (at block-blue bin) (at vial bin))
  (:goal (and (at jar rack-hi) (at cup mat)))
  (:metric minimize (total-cost)))
