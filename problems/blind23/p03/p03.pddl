; blind23 p03: three cans (r 3 cm, 8 cm tall) in a row along y, 1.5 cm
; apart; the middle one (soda) must be pushed 14 cm straight out of the row,
; away from the xArm6, into `goal`, without disturbing tea and cola.
; Cheapest (1) = expected: (push soda row-mid goal)
(define (problem p03)
  (:domain can-row)
  (:objects soda tea cola - can
            row-left row-mid row-right goal - zone)
  (:init (at tea row-left) (at soda row-mid) (at cola row-right))
  (:goal (and (at soda goal) (at tea row-left) (at cola row-right)
              (not (busy)))))
