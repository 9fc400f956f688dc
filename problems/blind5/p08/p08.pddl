; Panda: a tall box from under a low overhang (only a side grasp reaches
; it) into a deep bin (only a top grasp fits). One grip cannot do both: the
; box must be set down on the open table and picked again (a regrasp).
(define (problem blind5-p08)
  (:domain blind5-carry)
  (:objects box - thing
            nook spare bin - region)
  (:init (in box nook) (free))
  (:goal (in box bin)))
