; blind36 p03 (xArm6 behind the rack, turned 180 deg): put the carton (7 x 4 x 10 cm) onto the
; upper level's display spot, where the cup stands; the cup goes to the lower level beside the jar.
; Expected 4: take cup, put it on rack-lo, take carton, put it in hi-spot.
(define (problem p03)
  (:domain shelving)
  (:objects cup jar block-red block-blue ball carton nut vial - item
            hi-spot - spot
            mat bin drop rack-lo rack-hi - surface)
  (:init (handempty)
         (at cup hi-spot)
         (at carton mat) (at nut mat) (at jar rack-lo)
         (at block-red bin) (at block-blue bin) (at vial bin) (at ball drop))
  (:goal (and (at carton hi-spot) (at cup rack-lo))))
