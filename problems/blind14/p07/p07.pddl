; blind14 p07: a 5 cm cube, a can and a 4 cm cube from the near zone
; (0.43-0.45 m from the base) to the far zones (0.70-0.76 m).
(define (problem p07)
  (:domain kuka-store)
  (:objects big can small - item
            near far-w far-e - zone)
  (:init (in big near) (in can near) (in small near)
         (far far-w) (far far-e) (handfree))
  (:goal (and (stored big) (stored can) (stored small) (handfree))))
