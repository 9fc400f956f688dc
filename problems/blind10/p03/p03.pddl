;; Four boxes of different sizes, scattered and turned, built into one
;; tower on a small fixed plinth in a given order: slab at the bottom,
;; then brick, block, and cap on top.
(define (problem blind10-p03)
  (:domain blind10-build)
  (:objects slab brick block cap - piece
            plinth - stand
            yard - zone)
  (:init (in slab yard) (in brick yard) (in block yard) (in cap yard)
         (free-top slab) (free-top brick) (free-top block) (free-top cap)
         (free-top plinth) (idle))
  (:goal (and (upon slab plinth) (upon brick slab) (upon block brick)
              (upon cap block))))
