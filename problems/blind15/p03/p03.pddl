; blind15 p03: a tower base / mid / top stands in `home`; the base block at
; the bottom must end in `goal` with mid stacked back on it. Two parking
; zones. Untyped, negative preconditions.
(define (problem p03)
  (:domain xarm-unstack)
  (:objects base mid top home goal park-a park-b)
  (:init (block base) (block mid) (block top)
         (zone home) (zone goal) (zone park-a) (zone park-b)
         (at base home) (on mid base) (on top mid) (clear top))
  (:goal (and (at base goal) (on mid base))))
