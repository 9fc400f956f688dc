; blind16 p05: resting contact at the start. A thin upright book stands
; with its back face touching a fixed bookend; a cube stands touching the
; book's front face. Both go to their targets. Expected: 4 actions.
(define (problem p05)
  (:domain panda-contact)
  (:objects book cube - item
            shelf-spot book-goal cube-goal - area)
  (:init (at book shelf-spot) (at cube shelf-spot) (handempty)
         (target book book-goal) (target cube cube-goal))
  (:goal (and (done book) (done cube))))
