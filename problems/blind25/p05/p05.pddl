; blind25 p05: a cup with a plate on it (the plate wider than the cup) and a
; die on the plate. The cup must go to the tray, the plate to the rack, and
; the die back onto the plate.
; Cheapest symbolic (cost 11, 8 actions) = expected:
;   (unstack die plate) (put die side) (unstack plate cup) (put plate rack)
;   (pick die side) (stack die plate) (pick cup cup-spot) (put cup tray)
; (the cup's pair may also come right after the plate's)
(define (problem p05)
  (:domain dish-stack)
  (:objects cup plate die - item
            cup-spot tray rack side - spot)
  (:init (at cup cup-spot) (on plate cup) (on die plate) (clear die)
         (handempty) (= (total-cost) 0))
  (:goal (and (at cup tray) (at plate rack) (on die plate) (handempty)))
  (:metric minimize (total-cost)))
