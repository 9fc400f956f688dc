;; A thin slab stands in a tall-walled bin, 6.5 cm (centre to inner face)
;; from the bin's north wall, its thin side facing the wall; take it out
;; onto the rack pad.
(define (problem blind11-p01)
  (:domain blind11-liftout)
  (:objects slab - thing
            bin rack - spot)
  (:init (resting slab bin) (hand-idle))
  (:goal (and (resting slab rack) (hand-idle))))
