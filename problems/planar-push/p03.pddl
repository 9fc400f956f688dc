; A heavy crate that cannot be lifted: only the push skeleton is applicable.
(define (problem planar-push-p03)
  (:domain planar-push)
  (:objects crate - item
            start goal - region
            table - surface)
  (:init (at crate start) (handempty)
         (region-on start table) (region-on goal table)
         (= (total-cost) 0))
  (:goal (at crate goal))
  (:metric minimize (total-cost)))
