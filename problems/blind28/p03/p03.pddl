; Fill the bowl from the cup: the bowl must first be brought from its shelf
; spot to the mat (or the trivet), the cup held over it and poured, and the
; cup put back on its coaster.
(define (problem b28-p03)
  (:domain b28-pour)
  (:objects cup bowl coaster bowl-home)
  (:init (cup cup) (bowl bowl) (has-water cup) (handempty)
         (at cup coaster) (at bowl bowl-home)
         (spot coaster) (spot bowl-home) (spot mat) (spot trivet))
  (:goal (and (full bowl) (at cup coaster) (handempty)
              (or (at bowl mat) (at bowl trivet)))))
