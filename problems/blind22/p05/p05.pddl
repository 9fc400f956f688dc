; blind22 p05: a 4 cm cube stands in a nook: a fixed ledge (4.5 cm tall)
; 1.5 cm north of it, a movable bottle (cylinder r 2.5 cm, 15 cm tall)
; 1.5 cm west of it, east and south open. The goal spot is wide open; the
; bottle is not in the goal's way but in the hand's: every grip of the
; cube puts a finger into the ledge (fingers north/south) or into the
; bottle (fingers east/west), open or narrowed. With the bottle gone, a
; top grasp across the cube's x faces is free. A vase 1.10 m out, beyond
; the Panda's reach, in `far`, is a distractor no plan needs.
; Cheapest (2): (pick cube) (place cube goal): geometrically blocked.
; Expected (4): (pick bottle) (place bottle side|goal) (pick cube) (place cube goal)
(define (problem p05)
  (:domain approach-block)
  (:objects cube bottle vase - thing
            nook bottle-home goal side far - spot)
  (:init (at cube nook) (at bottle bottle-home) (at vase far) (handempty))
  (:goal (at cube goal)))
