; The goal region lies on a second table across a 4 cm gap: a push cannot
; leave its surface, so only pick + place reaches it.
(define (problem planar-push-p02)
  (:domain planar-push)
  (:objects box - item
            start goal - region
            table side-table - surface)
  (:init (at box start) (handempty) (liftable box)
         (region-on start table) (region-on goal side-table)
         (= (total-cost) 0))
  (:goal (at box goal))
  (:metric minimize (total-cost)))
