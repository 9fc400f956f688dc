; blind17 p04: a longer plan is cheaper. The cube's direct carry past
; the vase costs 10; through the relay spot it costs 2 + 2 (plus a second
; pick). The cup's direct carry costs 3, through the relay 2 + 2.
; Expected: 6 actions, cost 10 (the cube via the relay, the cup direct):
; (pick cube cube-home) (place cube cube-home relay) (pick cube relay)
; (place cube relay cube-goal) (pick cup cup-home) (place cup cup-home cup-goal)
; in some interleaving; the all-direct plan costs 15.
(define (problem p04)
  (:domain relay-costs)
  (:objects cube cup - item
            cube-home cup-home relay cube-goal cup-goal - spot)
  (:init (at cube cube-home) (at cup cup-home) (handempty)
         (link cube-home cube-goal) (= (carry-cost cube-home cube-goal) 10)
         (link cube-home relay)     (= (carry-cost cube-home relay) 2)
         (link relay cube-goal)     (= (carry-cost relay cube-goal) 2)
         (link cup-home cup-goal)   (= (carry-cost cup-home cup-goal) 3)
         (link cup-home relay)      (= (carry-cost cup-home relay) 2)
         (link relay cup-goal)      (= (carry-cost relay cup-goal) 2)
         (= (total-cost) 0))
  (:goal (and (at cube cube-goal) (at cup cup-goal)))
  (:metric minimize (total-cost)))
