(define (problem b31-p01) (:domain b31-sort)
  (:objects r1 r2 g1 g2 b1 b2 tin carton bottle - item
            red green blue - colour
            counter - surface
            red-bin green-bin blue-bin - bin)
  (:init (handempty)
         (at r1 counter) (at r2 counter) (at g1 counter) (at g2 counter)
         (at b1 counter) (at b2 counter)
         (at tin counter) (at carton counter) (at bottle counter)
         (colour-of r1 red) (colour-of r2 red)
         (colour-of g1 green) (colour-of g2 green)
         (colour-of b1 blue) (colour-of b2 blue)
         (bin-colour red-bin red) (bin-colour green-bin green) (bin-colour blue-bin blue)
         (sortable r1) (sortable r2) (sortable g1) (sortable g2) (sortable b1) (sortable b2))
  (:goal (forall (?o - item) (imply (sortable ?o) (sorted ?o)))))
