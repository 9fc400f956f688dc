;; A 2.2 cm thin slab, 11 cm long, stands 5.6 cm (centre to face) in front
;; of a wall as tall as the slab; move it to the pad on the left.
(define (problem blind12-p01)
  (:domain blind12-slab)
  (:objects slab - piece
            ledge pad - spot)
  (:init (sits slab ledge) (empty-hand))
  (:goal (and (sits slab pad) (empty-hand))))
