; Take the sample tube out of the booth onto the rack, and put the reagent
; bottle into the booth's empty spot, both through the wall's window.
(define (problem b29-p01)
  (:domain b29-hatch)
  (:objects sample reagent - item
            hood-a hood-b rack bench-out - zone)
  (:init (at sample hood-a) (at reagent bench-out) (hand-empty)
         (= (handling hood-a) 3) (= (handling hood-b) 3)
         (= (handling rack) 1) (= (handling bench-out) 1)
         (= (total-cost) 0))
  (:goal (and (at sample rack) (at reagent hood-b)))
  (:metric minimize (total-cost)))
