; Two ramekins from the pantry must be cooked and served on two plates.
(define (problem b28-p02)
  (:domain b28-oven)
  (:objects d1 d2 - dish pantry1 pantry2 oven-tray plate1 plate2 - spot)
  (:init (at d1 pantry1) (at d2 pantry2) (oven oven-tray) (= (total-cost) 0))
  (:goal (and (cooked d1) (cooked d2) (at d1 plate1) (at d2 plate2)))
  (:metric minimize (total-cost)))
