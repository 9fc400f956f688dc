; blind20 p05: two 5 cm cubes in a channel 9 cm wide between walls 6.5 cm
; tall, closed at the back: `back` 2 cm behind `front`, which stands at the
; mouth. The fingers cannot close across the channel on `back` (the walls
; are 2 cm from its faces; a finger is 2 cm thick, 4-6 cm from the axis)
; nor along it while `front` stands 2 cm in front of it. Only `back` is
; wanted, at `goal`.
; Cheapest (2): (pick back back-home) (place back goal): infeasible.
; Expected (4): (pick front front-home) (place front spare)
;               (pick back back-home) (place back goal)
(define (problem p05)
  (:domain channel)
  (:objects front back - cube
            front-home back-home - rack-spot
            goal spare - table-spot)
  (:init (at front front-home) (at back back-home)
         (free goal) (free spare) (handempty))
  (:goal (at back goal)))
