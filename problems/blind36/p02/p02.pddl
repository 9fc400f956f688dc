; blind36 p02 (KUKA iiwa at the far end, turned 180 deg): build a three-piece tower on the mat,
; block-blue (5.5 x 5.5 x 4 cm) at the bottom, block-red (4.5 cm cube) on it, the vial on top.
; Start: block-red alone on the mat, the vial standing on block-blue at spare.
; Expected 8: unstack vial, put it down, blue -> mat (beside red), red onto blue, vial onto red.
(define (problem p02)
  (:domain tower)
  (:objects cup jar block-red block-blue ball carton nut vial - piece
            mat bin drop spare rack-lo rack-hi - region)
  (:init (handempty)
         (at block-red mat) (clear block-red)
         (at block-blue spare) (on vial block-blue) (clear vial)
         (at cup rack-hi) (clear cup) (at nut rack-lo) (clear nut) (at jar rack-lo) (clear jar)
         (at carton drop) (clear carton) (at ball bin) (clear ball))
  (:goal (and (at block-blue mat) (on block-red block-blue) (on vial block-red))))
