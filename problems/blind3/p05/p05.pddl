; Panda: pack three boxes side by side into a tray on a platform; the tray
; is 13 x 7.5 cm, the boxes' footprints 4 x 7, 5 x 6 and 3 x 6.5 cm.
(define (problem blind3-p05)
  (:domain blind3-pick-place)
  (:objects a b c - obj
            start tray - region)
  (:init (at a start) (at b start) (at c start) (handempty))
  (:goal (and (at a tray) (at b tray) (at c tray))))
