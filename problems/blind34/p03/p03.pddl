; blind34 p03: unload, push twice, reload. A 12 cm crate (too wide for the
; KUKA's grip, and not liftable) carries a coaster, and a mug stands on the
; coaster. The crate must end in the dock, 20 cm along +x and 20 cm along +y
; (45 deg off every face's normal: outside the friction cone, so two pushes,
; through mid-a or mid-b), with the coaster on it and the mug on the coaster.
; A loaded crate cannot be pushed, nor a loaded coaster picked.
; Expected (10): (unstack mug coaster) (place mug aside) (unstack coaster crate)
;   (place coaster aside) (push crate home mid-a) (push crate mid-a dock)
;   (pick coaster aside) (stack coaster crate) (pick mug aside) (stack mug coaster)
;   [or via mid-b].
(define (problem p03)
  (:domain unload-push-reload)
  (:objects crate coaster mug - item
            home mid-a mid-b dock aside - zone)
  (:init (at crate home) (on coaster crate) (on mug coaster) (clear mug)
         (handempty) (liftable mug) (liftable coaster) (pushable crate))
  (:goal (and (at crate dock) (on coaster crate) (on mug coaster))))
