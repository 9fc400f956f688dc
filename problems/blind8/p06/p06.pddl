;; Panda: three 5.3 cm boxes into a tray 16.6 cm long between tall end walls.
(define (problem blind8-p06)
  (:domain blind8-pack)
  (:objects b1 b2 b3 - box
            s1 s2 s3 tray - spot)
  (:init (at b1 s1) (at b2 s2) (at b3 s3) (handempty))
  (:goal (and (at b1 tray) (at b2 tray) (at b3 tray))))
