; blind35 p01 (xArm6): a case 8.1 cm wide (the xArm6 takes at most 8.2 cm)
; onto a shelf spot where a clip stands. Expected: clip to spare, case to shelf.
(define (problem p01)
  (:domain edge-width)
  (:objects case clip - item
            case-home shelf spare - spot)
  (:init (at case case-home) (at clip shelf) (handempty))
  (:goal (and (at case shelf) (handempty))))
