; blind38 p06 (planar disk): every puck from the west room to the east room through a 20 cm door.
; Expected 4 actions.
(define (problem p06)
  (:domain door-fetch)
  (:objects p1 p2 - puck west east - room)
  (:init (empty) (in p1 west) (in p2 west))
  (:goal (forall (?p - puck) (in ?p east))))
