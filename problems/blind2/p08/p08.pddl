; Push-only obstruction: a small crate sits in the goal region of a big one;
; nothing can be lifted, so the small crate must be pushed aside first.
(define (problem blind2-p08)
  (:domain blind2-push)
  (:objects big small - item
            start goal siding - region
            bench - surface)
  (:init (at big start) (at small goal) (handempty)
         (region-on start bench) (region-on goal bench) (region-on siding bench)
         (= (total-cost) 0))
  (:goal (at big goal))
  (:metric minimize (total-cost)))
