;; Three mugs on the counter; four coasters in a row, the last holding a
;; bottle. Every mug must end on some coaster (any one), hand empty.
(define (problem blind11-p07)
  (:domain blind11-coasters)
  (:objects mug-1 mug-2 mug-3 - mug
            bottle - bottle
            c1 c2 c3 c4 - coaster
            counter - worktop)
  (:init (on-site mug-1 counter) (on-site mug-2 counter)
         (on-site mug-3 counter) (on-site bottle c4)
         (unoccupied c1) (unoccupied c2) (unoccupied c3)
         (empty-hand))
  (:goal (and (forall (?m - mug) (exists (?c - coaster) (on-site ?m ?c)))
              (empty-hand))))
