; Two tall occluders stand in the camera's sightline to the target. Clear
; the sightline, park the arm, look, then deliver the target.
(define (problem b28-p05)
  (:domain b28-lookout)
  (:objects target o1 o2 - thing
            view-spot sightline bay1 bay2 out park - zone)
  (:init (at target view-spot) (at o1 sightline) (at o2 sightline)
         (hand-empty) (parked)
         (view-spot view-spot) (sightline sightline) (park-zone park))
  (:goal (and (inspected target) (at target out))))
