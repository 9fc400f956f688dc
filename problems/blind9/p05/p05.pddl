;; KUKA iiwa: two parts into cells of a divided tray; the wrench onto rack
;; slot-1, which the spare screwdriver occupies (it may not go into a
;; cell: only onto a table area). slot-2 holds a gauge the goal ignores.
(define (problem blind9-p05)
  (:domain blind9-kit-rack)
  (:objects p-a p-b - part
            wrench spare gauge - tool
            c1 c2 c3 - cell
            slot-1 slot-2 - slot
            feed tool-mat drop-zone - area)
  (:init (at p-a feed) (at p-b feed) (at wrench tool-mat)
         (at spare slot-1) (at gauge slot-2)
         (free c1) (free c2) (free c3)
         (free feed) (free tool-mat) (free drop-zone)
         (hand-empty))
  (:goal (and (forall (?p - part) (exists (?c - cell) (at ?p ?c)))
              (at wrench slot-1))))
