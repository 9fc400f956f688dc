; Panda: sort four objects by shape: the two cans onto a round stool, the
; two boxes into a bay on the table.
(define (problem blind3-p07)
  (:domain blind3-pick-place)
  (:objects can1 can2 cube slab - obj
            mixed stool bay - region)
  (:init (at can1 mixed) (at can2 mixed) (at cube mixed) (at slab mixed) (handempty))
  (:goal (and (at can1 stool) (at can2 stool) (at cube bay) (at slab bay))))
