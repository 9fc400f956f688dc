;; xArm6: a gem ringed by four tall bottles goes into a walled bin; the
;; bottles must stand in their ring spots at the end.
(define (problem blind8-p08)
  (:domain blind8-retrieve)
  (:objects gem - gem
            bottle-e bottle-w bottle-n bottle-s - bottle
            pedestal ring-e ring-w ring-n ring-s aside bin - spot)
  (:init (at gem pedestal) (at bottle-e ring-e) (at bottle-w ring-w)
         (at bottle-n ring-n) (at bottle-s ring-s))
  (:goal (and (at gem bin) (at bottle-e ring-e) (at bottle-w ring-w)
              (at bottle-n ring-n) (at bottle-s ring-s) (not (busy)))))
