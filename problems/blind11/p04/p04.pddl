;; A jug stands at the back of a low-walled slot, a tin in front of it.
;; The jug goes to the tray and the tin to the back of the slot, where the
;; jug was: the tin must be moved out of the way first, and back in last.
(define (problem blind11-p04)
  (:domain blind11-slot)
  (:objects jug tin - good
            front back spare tray - place)
  (:init (kept jug back) (kept tin front)
         (vacant spare) (vacant tray)
         (open-place front) (open-place spare) (open-place tray)
         (guards front back)
         (hand-empty))
  (:goal (and (kept jug tray) (kept tin back) (hand-empty))))
