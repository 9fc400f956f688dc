; Swap the top two blocks of a tower of three, via two tight buffer pads
; side by side.
(define (problem b27-p03)
  (:domain b27-tower)
  (:objects a b c - block base buf1 buf2 - pad)
  (:init (on c base) (on b c) (on a b) (handempty))
  (:goal (and (on a c) (on b a) (on c base))))
