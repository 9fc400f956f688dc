;; Panda: two hexagonal prisms (one mesh file, two scales); the big flat
;; one, turned 30 deg, moves to zone-c, and the small tall one is stacked
;; on it: a mesh placed on a mesh.
(define (problem blind7-p05)
  (:domain blind7-nuts)
  (:objects big - nut
            small - washer
            zone-a zone-b zone-c - zone)
  (:init (placed big zone-a) (placed small zone-b) (= (total-cost) 0))
  (:goal (and (placed big zone-c) (stacked-on small big) (not (hand-occupied))))
  (:metric minimize (total-cost)))
