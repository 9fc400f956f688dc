; Three plates standing on edge on the counter go into the three slots of
; a dish rack, plate-k into slot-k. Expected, 6 actions:
; (take plate-k spot-k) (load plate-k slot-k) for k = 1..3, in some order.
(define (problem load-the-rack)
  (:domain dish-rack)
  (:objects plate-1 plate-2 plate-3 - plate
            spot-1 spot-2 spot-3 - spot
            slot-1 slot-2 slot-3 - slot)
  (:init (at plate-1 spot-1) (at plate-2 spot-2) (at plate-3 spot-3)
         (vacant slot-1) (vacant slot-2) (vacant slot-3) (handempty))
  (:goal (and (at plate-1 slot-1) (at plate-2 slot-2) (at plate-3 slot-3)
              (handempty))))
