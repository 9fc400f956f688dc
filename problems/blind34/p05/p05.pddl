; blind34 p05: a 4 cm square part hemmed in on four sides, 2.1 cm from each
; neighbour (a Panda finger is 2.6 cm thick): fixed posts on +-y, movable
; cans on +-x, and a third can beside them that blocks nothing. Only fingers
; closing along x can ever grip the part, so BOTH x-cans must go (either
; alone leaves a 2.1 cm gap on the other side); moving one, or the
; distractor, is useless. Expected (6): the two x-cans to `park`, then the part.
(define (problem p05)
  (:domain which-to-move)
  (:objects part can-near can-far can-side - thing
            cell near-spot far-spot side-spot park goal - spot)
  (:init (at part cell) (at can-near near-spot) (at can-far far-spot)
         (at can-side side-spot) (free))
  (:goal (at part goal)))
