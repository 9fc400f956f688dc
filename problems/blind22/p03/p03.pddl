; blind22 p03: the planar disk (r 5 cm) pushes a puck (cylinder r 3 cm,
; 4 cm tall) 47 cm east, straight through the 12.4 cm gap between two round
; posts, into `beyond`. The disk follows the puck through the gap with
; 1.2 cm a side when centred (the 1 cm margin leaves it +-2 mm), so the
; push's line must pass the gap's middle. `gate` (between the posts) is a
; costlier stop on the way.
; Cheapest (cost 5, 1 push) = expected: (push puck start beyond)
(define (problem p03)
  (:domain post-gap)
  (:objects puck - puck
            start gate beyond - zone)
  (:init (at puck start)
         (= (push-cost start beyond) 5) (= (push-cost beyond start) 5)
         (= (push-cost start gate) 3) (= (push-cost gate start) 3)
         (= (push-cost gate beyond) 3) (= (push-cost beyond gate) 3)
         (= (total-cost) 0))
  (:goal (at puck beyond))
  (:metric minimize (total-cost)))
