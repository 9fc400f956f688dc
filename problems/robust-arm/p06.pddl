; Four blocks of different lengths into one lane.
(define (problem robust-arm-p06)
  (:domain robust-arm)
  (:objects a b c d - block
            start lane - region)
  (:init (in a start) (in b start) (in c start) (in d start) (handempty)
         (same-surface start lane) (same-surface lane start)
         (= (total-cost) 0))
  (:goal (and (in a lane) (in b lane) (in c lane) (in d lane)))
  (:metric minimize (total-cost)))
