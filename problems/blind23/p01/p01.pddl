; blind23 p01: a 5 cm cube lies in a chute against a 4 cm kerb (1 cm from
; its +y face). It must be slid 18 cm along the kerb (+x) out of the chute,
; then picked from where the push left it and set on a shelf 15 cm high.
; Cheapest (3) = expected: (push cube chute out) (pick cube out)
; (place cube shelf-top)
(define (problem p01)
  (:domain chute-push-pick)
  (:objects cube - item
            chute out shelf-top - zone)
  (:init (at cube chute) (handempty)
         (slide chute out)
         (pickable out) (pickable shelf-top))
  (:goal (and (at cube shelf-top) (handempty))))
