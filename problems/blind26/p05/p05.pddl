; The arm hangs upside down 0.8 m above the table: stack a on b, move c
; to the goal region.
(define (problem b26-p05)
  (:domain b26-ceiling)
  (:objects a b c bench goal)
  (:init (block a) (block b) (block c) (region bench) (region goal)
         (at a bench) (at b bench) (at c bench)
         (clear a) (clear b) (clear c) (handempty))
  (:goal (and (on a b) (at c goal))))
