; blind14 p01: two red and two blue cubes in a row on the pile; each
; colour into its own bin.
(define (problem p01)
  (:domain kuka-sort)
  (:objects r1 r2 b1 b2 - cube
            pile red-bin blue-bin - area)
  (:init (in r1 pile) (in b1 pile) (in r2 pile) (in b2 pile)
         (colour-of r1 red) (colour-of r2 red)
         (colour-of b1 blue) (colour-of b2 blue)
         (free))
  (:goal (and (free)
              (forall (?c - cube)
                (and (imply (colour-of ?c red) (in ?c red-bin))
                     (imply (colour-of ?c blue) (in ?c blue-bin)))))))
