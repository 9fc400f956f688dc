; blind35 p02 (xArm6): a case 8.3 cm wide (the xArm6 takes at most 8.2 cm)
; onto a shelf spot where a clip stands. Expected: unsolvable, proved: no grasp of the case fits.
(define (problem p02)
  (:domain edge-width)
  (:objects case clip - item
            case-home shelf spare - spot)
  (:init (at case case-home) (at clip shelf) (handempty))
  (:goal (and (at case shelf) (handempty))))
