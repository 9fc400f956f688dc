; Size extremes for the xArm6: a case 8.0 cm wide (the xArm takes at most
; 8.2 cm) goes into the shipping zone, then a coin 1.6 cm tall (the lowest
; top grasp the xArm takes is 1.41 cm) goes on top of the case.
; Expected, 4 actions: (pick case shelf-zone) (put case ship)
; (pick coin coin-dish) (put-on coin case).
(define (problem extremes)
  (:domain pack-and-top)
  (:objects case coin - item
            shelf-zone coin-dish ship - zone)
  (:init (in case shelf-zone) (in coin coin-dish)
         (clear case) (clear coin) (handempty))
  (:goal (and (in case ship) (on coin case) (handempty))))
