; blind16 p02: red must go into the dock (a walled alcove open to -x),
; which blue fills; blue must go to green's spot s2. Order forced:
; green out of s2 (to the spare spot), blue into s2, red into the dock.
; yellow is clutter beside the way. Expected: 6 actions.
(define (problem p02)
  (:domain planar-shuffle)
  (:objects red blue green yellow - puck
            dock s1 s2 s3 spare - spot)
  (:init (at red s1) (at blue dock) (at green s2) (at yellow s3)
         (empty spare) (handempty))
  (:goal (and (at red dock) (at blue s2))))
