; blind19 p01: build one tower of all three pieces on the dais. The goal
; does not give the order; only block-a (5 cm) under block-b (4 cm) under
; the can (r 1.8 cm) stands. The can starts on block-a, block-b beside.
; Every cost-6 plan puts a piece on one narrower than it (refuted by the
; footprint rule); expected 8 actions:
; (unstack can block-a) (place can spare) (pick block-a west)
; (place block-a dais) (pick block-b mid) (stack block-b block-a)
; (pick can spare) (stack can block-b)
(define (problem p01)
  (:domain tower-order)
  (:requirements :universal-preconditions)
  (:objects block-a block-b can - piece
            west mid spare dais - place)
  (:init (at block-a west) (on can block-a) (clear can)
         (at block-b mid) (clear block-b)
         (free spare) (free dais) (tower-base dais)
         (handempty))
  (:goal (forall (?o - piece) (in-tower ?o))))
