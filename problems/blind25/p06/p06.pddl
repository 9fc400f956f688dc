; blind25 p06: a part lies at the bottom of a deep bin (walls 13 cm above
; its top); take it out onto `out`, then put the can into the bin.
; Cheapest symbolic (4) = expected (4 actions):
;   (pick part bin) (place part out) (pick can can-home) (place can bin)
(define (problem p06)
  (:domain deep-bin)
  (:objects part can - item
            bin out can-home - zone)
  (:init (at part bin) (at can can-home) (deep bin) (handempty))
  (:goal (and (at part out) (at can bin) (handempty))))
