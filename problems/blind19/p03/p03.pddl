; blind19 p03: the xArm6 puts a can and a tall carton from the table onto
; the top of a 35 cm cabinet, 0.61-0.70 m out: beyond where its hand
; pointing down reaches at that height (0.58 m at 0.40 m up, 0.48 m at
; 0.50 m), inside where a level hand reaches (0.14-0.88 m). Both must be
; taken from the side, at the table too (pick and place share the grip).
; Expected (4 actions): (pick can can-home) (place can shelf-l)
; (pick carton carton-home) (place carton shelf-r), either order.
(define (problem p03)
  (:domain high-shelf)
  (:objects can carton can-home carton-home shelf-l shelf-r)
  (:init (item can) (item carton)
         (spot can-home) (spot carton-home) (spot shelf-l) (spot shelf-r)
         (at can can-home) (at carton carton-home)
         (free shelf-l) (free shelf-r) (handempty))
  (:goal (and (at can shelf-l) (at carton shelf-r))))
