;; A 6.2 cm tin in the open and a 2.4 cm batten standing 7 cm (centre to
;; face) in front of a splashback: store both on their pads.
(define (problem blind12-p06)
  (:domain blind12-store)
  (:objects tin-1 - tin
            batten-1 - batten
            counter ledge tin-pad batten-pad - pad)
  (:init (at tin-1 counter) (at batten-1 ledge) (hand-empty))
  (:goal (and (at tin-1 tin-pad) (at batten-1 batten-pad) (hand-empty))))
