; Kit the duck, the ball and the can into the tote.
(define (problem b29-p03)
  (:domain b29-scara-kit)
  (:objects duck ball can - toy
            duck-home ball-home can-home tote - place)
  (:init (at duck duck-home) (at ball ball-home) (at can can-home)
         (hand-empty) (kit-place tote))
  (:goal (forall (?t - toy) (kitted ?t))))
