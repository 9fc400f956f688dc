;; A 4.5 cm wide carton goes into the 8.5 cm gap of a packed row of four
;; fixed boxes (2 cm to spare each side).
(define (problem blind12-p03)
  (:domain blind12-shelving)
  (:objects carton-1 - carton
            counter gap - place)
  (:init (stands carton-1 counter) (gripper-empty)
         (= (total-cost) 0))
  (:goal (and (stands carton-1 gap) (gripper-empty)))
  (:metric minimize (total-cost)))
