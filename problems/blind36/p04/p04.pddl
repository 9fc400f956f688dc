; blind36 p04 (Panda off the table's south edge, turned 90 deg): empty the bin.
; The bin holds the ball, the vial and block-blue; nothing may be left in it, and the hand must be
; empty (formats.md: a negated location alone is met while the object is held). Expected 6.
(define (problem p04)
  (:domain unload)
  (:objects cup jar block-red block-blue ball carton nut vial - item
            mat bin drop spare side rack-lo - region)
  (:init (handempty)
         (at ball bin) (at vial bin) (at block-blue bin)
         (at cup mat) (at block-red mat) (at nut mat) (at jar rack-lo) (at carton spare))
  (:goal (and (forall (?o - item) (not (at ?o bin))) (handempty))))
