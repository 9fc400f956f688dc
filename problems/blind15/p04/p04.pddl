; blind15 p04: a 20 cm bottle onto a small coaster (fixed cylinder) and a
; 24 cm bar, lying along x, into a 5 cm wide slot running along y between
; two low rails.
(define (problem p04)
  (:domain tall-and-thin)
  (:objects flask - bottle
            rod - bar
            coaster - fixture
            counter bench slot - zone)
  (:init (at flask counter) (at rod bench) (handempty)
         (= (total-cost) 0))
  (:goal (and (standing-on flask coaster) (at rod slot)))
  (:metric minimize (total-cost)))
