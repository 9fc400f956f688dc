(define (problem p02)
  (:domain kuka-bin)
  (:objects c1 c2 c3 - cube
            staging bin - place)
  (:init (on-place c1 staging) (on-place c2 staging) (on-place c3 staging)
         (empty-hand))
  (:goal (and (on-place c1 bin) (on-place c2 bin) (on-place c3 bin))))
