; Planar disk: swap a square block and a long block between two pads that
; each hold only one of them, on either side of a divider; a spare pad
; serves as the buffer.
(define (problem blind4-p05)
  (:domain blind4-carry)
  (:objects sq long - thing
            west east spare - region)
  (:init (in sq west) (in long east) (free))
  (:goal (and (in sq east) (in long west))))
