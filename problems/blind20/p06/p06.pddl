; blind20 p06: a 4 cm cube onto post-a (a fixed cylinder, r 3.0 cm, 12 cm
; tall: the cube's corners, 2.83 cm from its centre, leave it 2.2 mm of
; play) and a ball (sphere r 2.5 cm) onto post-b (r 2.6 cm, 15 cm tall:
; 1.5 mm of play), then the arm parks over `home`.
; Expected (5): (pick cube cube-home) (display cube post-a)
;               (pick ball ball-home) (display ball post-b) (park home)
; (the two exhibits in either order).
(define (problem p06)
  (:domain exhibits)
  (:objects cube ball - exhibit
            post-a post-b - post
            cube-home ball-home home - zone)
  (:init (on-table cube cube-home) (on-table ball ball-home) (handempty)
         (park-spot home))
  (:goal (and (on cube post-a) (on ball post-b) (parked))))
