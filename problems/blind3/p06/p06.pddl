; Panda: take a tall box from under a shelf's overhang and stand it on a
; pedestal in the open.
(define (problem blind3-p06)
  (:domain blind3-pick-place)
  (:objects box - obj
            under pedestal - region)
  (:init (at box under) (handempty))
  (:goal (at box pedestal)))
