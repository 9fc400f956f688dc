; KUKA iiwa: build a tower of three cubes (6, 5 and 4 cm) on a raised
; platform; the cubes start apart on the table.
(define (problem blind5-p05)
  (:domain blind5-tower)
  (:objects big mid small - block
            yard plinth - region)
  (:init (in big yard) (in mid yard) (in small yard)
         (clear big) (clear mid) (clear small) (free))
  (:goal (and (in big plinth) (on mid big) (on small mid))))
