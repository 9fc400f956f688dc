; Panda: move a two-block stack to another zone. The upper block must come
; off first and wait somewhere while the lower one moves (6 actions).
(define (problem blind6-p01)
  (:domain blind6-stacks)
  (:objects base cap - block
            dock pad side - zone)
  (:init (in base dock) (on cap base) (clear cap) (hand-empty))
  (:goal (and (in base pad) (on cap base))))
