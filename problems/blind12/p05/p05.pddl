;; A 2.5 cm wide key stands in a 5 cm slot between two fixed jaws
;; running along x; move it into a second slot, whose jaws run along y.
(define (problem blind12-p05)
  (:domain blind12-slots)
  (:objects key-1 - key
            slot-a slot-b - slot)
  (:init (seated key-1 slot-a) (open-hand))
  (:goal (and (seated key-1 slot-b) (open-hand))))
