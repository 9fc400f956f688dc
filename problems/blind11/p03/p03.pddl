;; A soda can stands in a cluster: three other cans and a jar stand round
;; it, 9 cm centre to centre; take the soda can to the cooler spot.
(define (problem blind11-p03)
  (:domain blind11-cans)
  (:objects soda can-a can-b can-c jar - container
            cluster cooler - area)
  (:init (inside soda cluster) (inside can-a cluster) (inside can-b cluster)
         (inside can-c cluster) (inside jar cluster) (hand-free))
  (:goal (and (inside soda cooler) (hand-free))))
