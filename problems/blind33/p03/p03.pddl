; A roofed cubby two deep: red in front, blue behind. Exchange them.
; The 6-action plan (red out, blue to the front, red to the back) seals the
; back slot before red gets there; 8 actions, via two buffers.
(define (problem b33-p03)
  (:domain b33-p03)
  (:objects red blue - item front back buf-a buf-b - spot)
  (:init (at red front) (at blue back) (handempty))
  (:goal (and (at red back) (at blue front))))
