; blind15 p07: carry the puck through a two-turn maze into either dock of
; the far room (an existential goal).
(define (problem p07)
  (:domain planar-maze)
  (:objects token start-pad hall dock-ne dock-nw)
  (:init (puck token) (spot start-pad) (spot hall) (spot dock-ne) (spot dock-nw)
         (dock dock-ne) (dock dock-nw)
         (at token start-pad) (idle))
  (:goal (exists (?d) (and (dock ?d) (at token ?d)))))
