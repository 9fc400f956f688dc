; blind15 p08: build can / cap / coin on the pedestal; the goal says only
; that the coin is grounded and the order of the pieces, so the can must go
; on the pedestal first.
(define (problem p08)
  (:domain tight-stack)
  (:objects can cap coin - piece
            post - pedestal
            bench - zone)
  (:init (at can bench) (at cap bench) (at coin bench)
         (clear can) (clear cap) (clear coin) (clear post)
         (grounded post) (handempty))
  (:goal (and (grounded coin) (on coin cap) (on cap can))))
