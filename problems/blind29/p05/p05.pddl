; Get the heavy weight onto the seesaw's plank (and leave it standing).
(define (problem b29-p05)
  (:domain b29-seesaw)
  (:objects heavy light - weight
            plank - board
            heavy-home light-home - zone)
  (:init (at heavy heavy-home) (at light light-home) (hand-empty))
  (:goal (exists (?b - board) (on-board heavy ?b))))
