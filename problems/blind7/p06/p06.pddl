;; Panda: a spool carried over a 15 cm fence (a URDF body) into a bay
;; beside a wedge (a mesh), inspected on the way.
(define (problem blind7-p06)
  (:domain blind7-stow)
  (:objects spool1 - spool
            src dst - bay)
  (:init (stowed spool1 src) (hand-idle) (= (total-cost) 0))
  (:goal (and (stowed spool1 dst) (inspected spool1) (hand-idle)))
  (:metric minimize (total-cost)))
