;; Panda: push a crate and a drum (neither liftable) into their zones; a
;; cube stands in the crate's lane, a cup in the drum's zone; the cup goes
;; into a tray.
(define (problem blind8-p05)
  (:domain blind8-push-pick)
  (:objects crate drum cube cup - obj
            c-start dock lane side d-start d-goal c0 tray - zone)
  (:init (at crate c-start) (at drum d-start) (at cube lane) (at cup c0)
         (liftable cube) (liftable cup) (handempty)
         (= (total-cost) 0))
  (:goal (and (at crate dock) (at drum d-goal) (at cup tray)))
  (:metric minimize (total-cost)))
