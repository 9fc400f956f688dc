;; Panda: swap red and blue between pad-a and pad-b. The only spare spot,
;; side, is taken by green, whose goal is the walled bin.
(define (problem blind8-p01)
  (:domain blind8-rearrange)
  (:objects red blue green - item
            pad-a pad-b side bin - spot)
  (:init (on red pad-a) (on blue pad-b) (on green side) (hand-free))
  (:goal (and (on red pad-b) (on blue pad-a) (on green bin))))
