;; KUKA iiwa: a carton from the lower level of a two-level shelf (under the
;; upper board) to the upper level.
(define (problem blind7-p02)
  (:domain blind7-shelving)
  (:objects carton1 - carton
            lower upper - board)
  (:init (sits carton1 lower) (= (total-cost) 0))
  (:goal (and (sits carton1 upper) (not (busy))))
  (:metric minimize (total-cost)))
