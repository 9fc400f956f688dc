; blind15 p02: fetch the bottle from under the shelf board to the tray, and
; store the can under the shelf (in either shelf zone).
(define (problem p02)
  (:domain kuka-shelf)
  (:objects bottle can shelf-low shelf-spot tray counter)
  (:init (item bottle) (item can)
         (zone shelf-low) (zone shelf-spot) (zone tray) (zone counter)
         (shelf shelf-low) (shelf shelf-spot)
         (at bottle shelf-low) (stored bottle) (at can counter) (free))
  (:goal (and (at bottle tray) (stored can))))
