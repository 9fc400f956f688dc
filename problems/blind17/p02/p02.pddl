; blind17 p02: the cube must end on the slab, and the slab on the dais.
; The slab must be moved before the cube goes onto it (a block with
; something on it cannot be picked). Expected: 4 actions, cost 4:
; (pick slab slab-home) (place slab dais) (pick cube cube-home) (stack cube slab)
(define (problem p02)
  (:domain stack-after-move)
  (:objects slab cube slab-home cube-home dais)
  (:init (block slab) (block cube)
         (spot slab-home) (spot cube-home) (spot dais)
         (at slab slab-home) (at cube cube-home)
         (occupied slab-home) (occupied cube-home)
         (clear slab) (clear cube) (handempty))
  (:goal (and (at slab dais) (on cube slab))))
