;; Planar disk in a maze: carry one crate from the first corridor to the
;; last, through three serpentine walls and past two pillars.
(define (problem blind7-p03)
  (:domain blind7-courier)
  (:objects box1 - crate
            inlet outlet - dock)
  (:init (lies box1 inlet) (= (total-cost) 0))
  (:goal (and (lies box1 outlet) (not (suction-on))))
  (:metric minimize (total-cost)))
