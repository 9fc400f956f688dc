(define (problem p08)
  (:domain xarm-nest)
  (:objects cube stone - piece
            dock nest spare - area)
  (:init (at cube dock) (at stone nest))
  (:goal (and (at cube nest) (not (hand-busy)))))
