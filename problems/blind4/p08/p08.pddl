; KUKA iiwa: stand a can on a raised stand, in the 9 cm gap between two posts.
(define (problem blind4-p08)
  (:domain blind4-carry)
  (:objects can - thing
            mat gap - region)
  (:init (in can mat) (free))
  (:goal (in can gap)))
