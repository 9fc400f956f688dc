; blind37 p03: task A; every support holds one thing (derived `covered`); the base of the
; tower goes onto some stand (the dais, a fixed body). Expected 8 actions, the cube parked at park.
(define (problem p03)
  (:domain tower-derived)
  (:objects plate drum cube - piece
            dais - stand
            left right park - zone)
  (:init (on plate left) (on cube plate) (on drum right))
  (:goal (and (exists (?t - stand) (on plate ?t))
              (on drum plate) (on cube drum)
              (not (hand-busy)))))
