; blind15 p06: the box must go from the west room to the east goal, through
; the only passage, an 18 cm corridor in which a crate (not liftable) sits.
; The PDDL does not say the crate is in the way: the cheapest plan (pick,
; place) runs into it; the crate can be pushed on east into east-bay.
(define (problem p06)
  (:domain planar-corridor)
  (:objects crate box - thing
            corridor east-bay box-home east-goal - zone)
  (:init (at crate corridor) (at box box-home)
         (handempty) (liftable box)
         (= (total-cost) 0))
  (:goal (at box east-goal))
  (:metric minimize (total-cost)))
