; blind34 p01: build a tower of two, any two of three pieces, on the pad
; under a low hood (board bottom 16 cm over the table). The goal does not
; say which pieces: the tall can (14 cm) fits under the hood alone but not
; in any tower of two; the short puck cannot carry the block (box on a
; narrower disk); so only (block on pad, puck on block) stands.
; Every grip at the pad must be a side grasp (a hand from above meets the hood).
(define (problem p01)
  (:domain low-hood-tower)
  (:objects block puck can - piece
            block-home puck-home can-home pad - spot)
  (:init (on-spot block block-home) (on-spot puck puck-home)
         (on-spot can can-home)
         (clear block) (clear puck) (clear can))
  (:goal (exists (?x - piece ?y - piece)
           (and (on ?x ?y) (on-spot ?y pad)))))
