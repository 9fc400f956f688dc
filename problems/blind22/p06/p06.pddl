; blind22 p06: snug regions fix the yaw. A tile (box 5 x 3 x 4 cm) starts
; turned 30 deg and must be seated in `slot`, 5.4 x 3.4 cm (its long side
; along x, yaw 0 or 180 within +-4.7 deg), between two 1 cm kerbs 1 mm
; outside the slot's long edges. A peg (cylinder r 2 cm, 6 cm tall) must be
; seated in `ring`, 4.2 x 4.2 cm (its centre within 1 mm of the ring's),
; inside a 2 cm collar 1 mm outside the ring's edges: no yaw to choose,
; only the position. `spare` is a parking spot no plan needs.
; Cheapest (4 actions, cost 6) = expected:
;   (pick tile tile-home) (seat tile slot) (pick peg peg-home) (seat peg ring)
(define (problem p06)
  (:domain snug-sockets)
  (:objects tile peg - piece
            slot ring - socket
            tile-home peg-home spare - place)
  (:init (at tile tile-home) (at peg peg-home) (handempty)
         (socket-for tile slot) (socket-for peg ring)
         (= (total-cost) 0))
  (:goal (forall (?o - piece) (seated ?o)))
  (:metric minimize (total-cost)))
