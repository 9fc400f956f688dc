; 2 x 2 sliding-tile puzzle: rotate the three tiles two steps clockwise.
; Cells clockwise: nw -> ne -> se -> sw -> nw. Start: a nw, b ne, c se,
; sw empty. Goal: a se, b sw, c nw (ne empty). Every tile moves twice:
; 6 slides, e.g. (slide c se sw) (slide b ne se) (slide a nw ne)
; (slide c sw nw) (slide b se sw) (slide a ne se).
(define (problem slide-rotate-two)
  (:domain slide-puzzle)
  (:objects a b c - tile
            c-nw c-ne c-se c-sw - cell)
  (:init (at a c-nw) (at b c-ne) (at c c-se) (empty c-sw)
         (adj c-nw c-ne) (adj c-ne c-nw)
         (adj c-ne c-se) (adj c-se c-ne)
         (adj c-se c-sw) (adj c-sw c-se)
         (adj c-sw c-nw) (adj c-nw c-sw))
  (:goal (and (at a c-se) (at b c-sw) (at c c-nw))))
