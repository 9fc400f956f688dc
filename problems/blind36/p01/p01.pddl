; blind36 p01 (Panda at the origin): end-of-day tidy-up of the counter mat.
; cup -> upper rack level, block-red -> bin (already holding block-blue and the vial),
; nut (a mesh) -> lower rack level (already holding the jar). Expected: 6 actions.
(define (problem p01)
  (:domain tidy)
  (:objects cup jar block-red block-blue ball carton nut vial - item
            mat bin drop spare rack-lo rack-hi - region)
  (:init (handempty)
         (at cup mat) (at block-red mat) (at nut mat)
         (at jar rack-lo) (at carton spare) (at ball drop)
         (at vial bin) (at block-blue bin))
  (:goal (and (at cup rack-hi) (at block-red bin) (at nut rack-lo))))
