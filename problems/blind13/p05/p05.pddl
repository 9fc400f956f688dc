(define (problem p05)
  (:domain panda-pack)
  (:objects k1 k2 k3 - cube
            table-left well - spot)
  (:init (resting k1 table-left) (resting k2 table-left) (resting k3 table-left)
         (idle))
  (:goal (forall (?c - cube) (resting ?c well))))
