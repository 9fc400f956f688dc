; corner: push the crate around a right-angled corner. Expected: two pushes,
; (push crate start corner bench) (push crate corner goal bench).
(define (problem robust-push-corner)
  (:domain robust-planar-push)
  (:objects crate - item
            start corner goal - region
            bench - surface)
  (:init (at crate start) (handempty)
         (region-on start bench) (region-on corner bench) (region-on goal bench)
         (= (total-cost) 0))
  (:goal (at crate goal))
  (:metric minimize (total-cost)))
