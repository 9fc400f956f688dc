;; xArm6: a flat lid (r 3.1 cm, 2.2 cm tall) onto an open jar (r 3.6 cm,
;; 9.4 cm tall) standing 2.4 cm from a taller jar that must stay open.
(define (problem blind9-p02)
  (:domain blind9-capping)
  (:objects lid-a - lid
            jar-a jar-b - jar
            saucer - zone)
  (:init (lid-at lid-a saucer) (open jar-a) (open jar-b) (gripper-empty))
  (:goal (capped jar-a lid-a)))
