; blind14 p03: build plate / drum / cap in the stand.
(define (problem p03)
  (:domain panda-mixed-tower)
  (:objects plate - plate
            drum - drum
            cap - cube
            pad stand - area)
  (:init (in plate pad) (in drum pad) (in cap pad)
         (clear plate) (clear drum) (clear cap) (hand-empty))
  (:goal (and (in plate stand) (on drum plate) (on cap drum))))
