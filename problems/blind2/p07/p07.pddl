; Push a crate too wide to grasp into a garage under a low roof.
(define (problem blind2-p07)
  (:domain blind2-arm-push)
  (:objects crate - block
            apron garage - region)
  (:init (in crate apron) (handempty) (= (total-cost) 0))
  (:goal (in crate garage))
  (:metric minimize (total-cost)))
