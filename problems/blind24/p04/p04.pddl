; blind24 p04: any two of four cans into the bin. can-1 and can-2 stand
; near it; can-3 stands behind a tall fixed screen; can-4 stands 1.10 m
; from the base, beyond the Panda's reach (a distractor).
; Cheapest (4): two picks and places of any two distinct cans; expected:
;   (pick can-2 spot-2) (place can-2 bin) (pick can-1 spot-1) (place can-1 bin)
;   (either order)
(define (problem p04)
  (:domain two-of-four)
  (:objects can-1 can-2 can-3 can-4 - can
            spot-1 spot-2 spot-3 spot-4 bin - zone)
  (:init (at can-1 spot-1) (at can-2 spot-2) (at can-3 spot-3) (at can-4 spot-4)
         (bin bin) (handempty))
  (:goal (and (handempty)
              (exists (?x ?y - can)
                (and (not (= ?x ?y)) (binned ?x) (binned ?y))))))
