;; A vial stands on the table; it must go into a deep open crate whose
;; walls rise 12.8 cm above its floor, 5.6 cm above the
;; vial's top once it stands there.
(define (problem blind10-p02)
  (:domain blind10-load)
  (:objects vial - part
            crate-bottom - well
            pad - area)
  (:init (sits vial pad) (arm-free))
  (:goal (sits vial crate-bottom)))
