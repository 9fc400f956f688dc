; blind21 p02: the KUKA iiwa takes a thin wafer (7.0 x 7.0 x 1.6 cm) off a
; low shelf (5 cm high) and sets it into a goal region on the table whose
; north third lies under a hood (a board 10-12 cm above the table).
; The wafer itself fits under the hood, the hand does not: the wafer must
; end in the open part of the region (13 of its 20 cm along y).
; Expected (2): (pick wafer shelf-a) (place wafer goal).
(define (problem p02)
  (:domain wafer)
  (:objects wafer - wafer
            shelf-a shelf-b - shelf-spot
            goal - table-spot)
  (:init (at wafer shelf-a) (occupied shelf-a) (handempty))
  (:goal (at wafer goal)))
