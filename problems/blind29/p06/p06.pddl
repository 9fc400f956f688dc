; Deliver the ball, the puck and the brick to their bins on the east side
; of the partition. The battery starts full (two deliveries).
(define (problem b29-p06)
  (:domain b29-battery)
  (:objects ball puck brick - item
            ball-home puck-home brick-home bin-1 bin-2 bin-3 dock - zone)
  (:init (at ball ball-home) (at puck puck-home) (at brick brick-home)
         (hand-empty) (battery l2) (next l0 l1) (next l1 l2) (dock dock))
  (:goal (and (at ball bin-1) (at puck bin-2) (at brick bin-3))))
