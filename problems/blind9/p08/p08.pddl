;; Panda: a ball (sphere), a box, a can and a puck sorted by colour. The
;; red tray (13 x 9 cm inside a 1.5 cm rim) holds the blue can in its
;; middle, leaving 4.1 cm either side: neither red item fits until the can
;; is out.
(define (problem blind9-p08)
  (:domain blind9-sorting)
  (:objects ball box can puck - item
            bench red-tray blue-mat - zone
            red blue - colour)
  (:init (at ball bench) (at box bench) (at puck bench) (at can red-tray)
         (item-colour ball red) (item-colour box red)
         (item-colour can blue) (item-colour puck blue)
         (zone-colour red-tray red) (zone-colour blue-mat blue)
         (empty-hand))
  (:goal (forall (?o - item) (sorted ?o))))
