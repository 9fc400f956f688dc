;; Planar disk, push only: a puck (r 3.7 cm) shoved 43 cm into a round-ish
;; pocket open towards it (walls 6.3 cm from the pocket's centre, region
;; 8.6 cm square), and a crate turned 12 deg shoved 38 cm at 25 deg
;; (13 deg off its face normal) into a bay.
(define (problem blind9-p04)
  (:domain blind9-shove)
  (:objects disc - puck
            box - crate
            disc-home box-home pocket bay - zone)
  (:init (inside disc disc-home) (inside box box-home))
  (:goal (and (inside disc pocket) (inside box bay))))
