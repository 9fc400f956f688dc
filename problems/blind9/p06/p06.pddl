;; xArm6: vial-1 (clean) and block-2 (dirty) must both be inspected at the
;; one-sample station on a plinth beside a camera post; vial-1 must then
;; end in out-1, block-2 may stay at the station.
(define (problem blind9-p06)
  (:domain blind9-qa-cell)
  (:objects vial-1 block-2 - sample
            rack-a rack-b insp out-1 - spot
            wiper - pad)
  (:init (on vial-1 rack-a) (on block-2 rack-b)
         (clear insp) (clear out-1)
         (station insp) (clean vial-1) (hand-free))
  (:goal (and (inspected vial-1) (inspected block-2) (on vial-1 out-1))))
