(define (problem b31-p05) (:domain b31-setting)
  (:objects plate-1 plate-2 - plate
            cup fork knife salt pepper jar vase - thing
            counter mat fork-spot knife-spot vase-spot - zone)
  (:init (handempty)
         (at plate-1 counter) (on plate-2 plate-1) (topped plate-1)
         (at cup counter) (at fork counter) (at knife counter)
         (at salt counter) (at pepper counter) (at jar counter)
         (at vase vase-spot))
  (:goal (and (exists (?p - plate) (and (at ?p mat) (on cup ?p)))
              (at fork fork-spot) (at knife knife-spot) (handempty))))
