; blind18 p03: a 4 x 4 x 10 cm gauge block stands in a nook under a low
; board (2.5 cm over its top: no top grasp) and must go into a trench
; between two walls 5 mm from its faces and 1.5 cm higher than its top (no
; side grasp). No one grip does both ends: put it down on the open spare
; mat and take it again from above (a regrasp).
; Expected: skeleton #1 (pick gauge nook) (place gauge trench) fails; the
; answer, 4 actions (cost 4):
; (pick gauge nook) (place gauge spare) (pick gauge spare) (place gauge trench)
(define (problem p03)
  (:domain regrasp)
  (:objects gauge - part
            nook spare trench - zone)
  (:init (at gauge nook) (handempty))
  (:goal (and (at gauge trench) (handempty))))
