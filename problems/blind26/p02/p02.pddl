; The direct push home -> corner is the cheapest (cost 1) but runs 54 deg
; off every face normal of the crate; home -> lane -> corner costs 2.
(define (problem b26-p02)
  (:domain b26-corner-push)
  (:objects crate1 - crate home lane corner - spot)
  (:init (at crate1 home)
         (link home lane) (link lane corner) (link home corner)
         (= (push-cost home lane) 1) (= (push-cost lane corner) 1)
         (= (push-cost home corner) 1)
         (= (total-cost) 0))
  (:goal (at crate1 corner))
  (:metric minimize (total-cost)))
