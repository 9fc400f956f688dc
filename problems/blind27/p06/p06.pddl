; Shift every part of a three-slot rack one slot along and put the new part
; into the first: only one order works, and the PDDL does not know it.
(define (problem b27-p06)
  (:domain b27-rack)
  (:objects amber blue coral)
  (:init (part amber) (part blue) (part coral)
         (spot s1) (spot s2) (spot s3) (spot bench)
         (at amber s1) (at blue s2) (at coral bench) (handempty))
  (:goal (and (at coral s1) (at amber s2) (at blue s3))))
