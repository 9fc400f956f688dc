;; xArm6: one tall flask out of a shelf slot under a top board, onto the table.
(define (problem slot)
  (:domain blind8-fetch)
  (:objects flask - container slot dst - place)
  (:init (at flask slot) (empty-hand))
  (:goal (at flask dst)))
