;; The core is at the bottom of a three-block tower; it must go to the
;; dock. The two blocks on it have to come off first; where they go is
;; free (two small side spots, or piled on each other).
(define (problem blind10-p06)
  (:domain blind10-pile)
  (:objects core mid lid - block
            stand dock side-a side-b - spot)
  (:init (placed core stand) (atop mid core) (atop lid mid) (bare lid)
         (empty-hand))
  (:goal (placed core dock)))
