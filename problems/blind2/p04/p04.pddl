; A pen with one opening holds two blockers of different sizes; the target
; must go in. Each blocker has a bay that fits it, and the big one fits only
; the big bay; the target's dock fits only the target.
(define (problem blind2-p04)
  (:domain blind2-planar)
  (:objects t big small - block
            dock pen bay-big bay-small - region)
  (:init (in t dock) (in big pen) (in small pen) (handempty))
  (:goal (in t pen)))
