; blind21 p06: the KUKA iiwa pushes a crate (9 x 9 x 6 cm: too wide for its
; 7.5 cm grip, so it can only be pushed) 42 cm north along a low kerb
; (1.5 cm tall, 1 cm east of the crate) into the corner the kerb makes with
; an 8 cm wall. A 4 cm cube stands in the crate's way, 6 cm short of the
; corner region; six fixed posts and a bottle stand round the goal and do
; not matter.
; Cheapest (1): (push crate corner): the crate runs into the cube.
; Expected (2): (push cube aside) (push crate corner)
;   (or 3 with the cube carried: (pick cube) (place cube aside)
;   (push crate corner)).
(define (problem p06)
  (:domain kerb-push)
  (:objects crate cube - thing
            crate-home cube-home aside corner - zone)
  (:init (at crate crate-home) (at cube cube-home) (handempty))
  (:goal (at crate corner)))
