; Clean the cabbage, cook it, and return home: 10 actions
;   move home counter, pick, move counter sink, place, clean,
;   pick, move sink stove, place, cook, move stove home.
(define (problem arm-kitchen-p01)
  (:domain arm-kitchen)
  (:objects cabbage - item
            home counter sink stove - region)
  (:init (at cabbage counter) (arm-at home) (handempty)
         (is-sink sink) (is-stove stove))
  (:goal (and (cooked cabbage) (arm-at home))))
