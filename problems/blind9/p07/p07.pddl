;; Planar disk: four crates of one class. ca shoved into dock-a; cb shoved
;; into dock-b once cd, parked there, is shoved aside; cc stands 1.5 cm
;; from the back wall, so no shove can move it away from the wall: it
;; must be latched and dragged to dock-c.
(define (problem blind9-p07)
  (:domain blind9-crates)
  (:objects ca cb cc cd - crate
            a-home b-home c-home dock-a dock-b dock-c side - zone)
  (:init (in ca a-home) (in cb b-home) (in cc c-home) (in cd dock-b)
         (unloaded))
  (:goal (and (in ca dock-a) (in cb dock-b) (in cc dock-c))))
