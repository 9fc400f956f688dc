; blind16 p03: pack a cube, a can and a bar into one shallow tray
; (forall goal). Expected: 3 picks and 3 places, 6 actions.
(define (problem p03)
  (:domain panda-pack)
  (:objects cube can bar - item
            cube-home can-home bar-home tray - area)
  (:init (at cube cube-home) (at can can-home) (at bar bar-home)
         (handempty))
  (:goal (forall (?o - item) (at ?o tray))))
