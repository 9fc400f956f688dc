; Three pieces into a U-shaped pocket (open to the west) that they fill:
; a slab 8 x 14 cm and two boxes 6 x 7 cm, in a 14.6 x 14.6 cm pocket.
(define (problem b27-p05)
  (:domain b27-pack)
  (:objects slab p q - piece home-s home-p home-q pocket - area)
  (:init (at slab home-s) (at p home-p) (at q home-q) (handempty))
  (:goal (forall (?o - piece) (at ?o pocket))))
