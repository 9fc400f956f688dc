; Rendezvous: bring the mug and the coaster together on ONE mat, whichever.
; The symbolic cheapest answers (cost 2) carry one of them onto the other's
; mat, but mat-a and mat-b are each only big enough for one of the two.
; Only mat-c holds both: expected (pick mug mat-a) (place mug mat-c)
; (pick coaster mat-b) (place coaster mat-c), 4 actions (either order).
(define (problem rendezvous)
  (:domain mats)
  (:requirements :existential-preconditions)
  (:objects mug coaster - item
            mat-a mat-b mat-c - mat)
  (:init (on-mat mug mat-a) (on-mat coaster mat-b) (handempty))
  (:goal (and (handempty)
              (exists (?m - mat) (and (on-mat mug ?m) (on-mat coaster ?m))))))
