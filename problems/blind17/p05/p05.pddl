; blind17 p05: evacuate the hazard zone. Three pucks stand in it; the
; goal says only that none is there (and the disk holds nothing), not
; where they go. safe-near (8 x 8 cm) takes one 6 cm puck; safe-far
; (20 x 20 cm) takes all three. Expected: 6 actions, cost 6, one puck
; (likely p3, the northern one) to safe-near, two to safe-far.
(define (problem p05)
  (:domain evacuate)
  (:objects p1 p2 p3 - puck
            hazard safe-near safe-far - zone)
  (:init (at p1 hazard) (at p2 hazard) (at p3 hazard) (handempty))
  (:goal (and (handempty)
              (forall (?p - puck) (not (at ?p hazard))))))
