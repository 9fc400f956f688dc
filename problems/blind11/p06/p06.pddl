;; A puck sits at the back of a recess whose mouth a heavy crate blocks:
;; shove the crate aside, then fetch the puck and drop it on the goal.
(define (problem blind11-p06)
  (:domain blind11-shove)
  (:objects crate puck - thing
            mouth alcove side-bay goal - zone)
  (:init (in-zone crate mouth) (in-zone puck alcove)
         (light puck)
         (recess alcove mouth)
         (open-zone mouth) (open-zone side-bay) (open-zone goal)
         (clear side-bay) (clear goal)
         (unloaded))
  (:goal (and (in-zone puck goal) (unloaded))))
