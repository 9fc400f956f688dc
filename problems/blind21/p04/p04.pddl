; blind21 p04: the xArm6 builds a mixed tower on a drum that stays where it
; is: the block (box 4.5 x 4.5 x 4 cm) onto the drum (cylinder r 3.5 cm,
; 7 cm tall), then the can (cylinder r 2 cm, 6 cm tall) onto the block.
; Windows: the block's corners (3.18 cm from its centre) within 3.55 cm of
; the drum's axis; the can's centre within 2.5 mm + 0.5 mm of the block's
; centre along each axis. The tower's top ends 17 cm above the table.
; Costs: lift drum 4, block 2, can 1; every set-down 1.
; Cheapest (cost 5, 4 actions) = expected:
;   (pick block block-home) (stack block drum) (pick can can-home)
;   (stack can block)
(define (problem p04)
  (:domain mixed-stack)
  (:objects drum - drum
            block - block
            can - can
            mat block-home can-home spare - zone)
  (:init (on-zone drum mat) (on-zone block block-home) (on-zone can can-home)
         (clear drum) (clear block) (clear can) (handempty)
         (= (lift-cost drum) 4) (= (lift-cost block) 2) (= (lift-cost can) 1)
         (= (total-cost) 0))
  (:goal (and (on block drum) (on can block)))
  (:metric minimize (total-cost)))
