; KUKA iiwa: build the tower a-b-c (c at the bottom) on a raised pad, from
; three boxes of decreasing size standing apart, each turned its own way.
(define (problem blind3-p01)
  (:domain blind3-stack)
  (:objects a b c - box
            floor pad - region)
  (:init (at a floor) (at b floor) (at c floor)
         (clear a) (clear b) (clear c) (handempty))
  (:goal (and (at c pad) (on b c) (on a b))))
