; against: place b snugly against a, which already fills the far end of the
; dock. Expected: 2 actions.
(define (problem robust-against)
  (:domain robust-planar)
  (:objects a b - block
            table dock - region)
  (:init (in a dock) (in b table) (handempty))
  (:goal (and (in a dock) (in b dock))))
