;; A crate too heavy to lift (and too wide to grip) must be shoved into
;; the bay, through the lane where a cup stands; then the tag goes on
;; top of the crate.
(define (problem blind10-p08)
  (:domain blind10-clear)
  (:objects crate - crate
            cup tag - small
            c-home lane bay spare rack - zone)
  (:init (located crate c-home) (located cup lane) (located tag rack)
         (cleared bay) (cleared spare)
         (between c-home lane bay) (dock bay)
         (top-free crate) (free-gripper))
  (:goal (and (located crate bay) (on-top tag crate))))
