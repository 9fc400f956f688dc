; blind24 p05: deliver a parcel from the west room to the east room round
; the end of a wall, and visit two checkpoints, in any order (the disk may
; visit them while carrying the parcel).
; Cheapest (4): 12 orders; expected, the one that lies on the way:
;   (grab parcel pad) (go cp-n) (go cp-e) (drop parcel dropzone)
(define (problem p05)
  (:domain deliver-and-visit)
  (:objects parcel pad dropzone cp-n cp-e)
  (:init (parcel parcel) (spot pad) (spot dropzone)
         (waypoint cp-n) (waypoint cp-e)
         (at parcel pad) (free-hand))
  (:goal (and (at parcel dropzone) (visited cp-n) (visited cp-e))))
