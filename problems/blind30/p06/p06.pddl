(define (problem b30-p06) (:domain b30-inspect)
  (:objects part - item intake bin - zone scanner - station)
  (:init (at part intake) (handempty) (outbox bin))
  (:goal (and (at part bin) (reported part))))
