;; KUKA iiwa: three parts into a walled bin whose floor a long piece of
;; junk blocks. The goal does not mention the junk.
(define (problem blind8-p02)
  (:domain blind8-kitting)
  (:objects p1 p2 p3 junk - thing
            feed-1 feed-2 feed-3 bin discard - zone)
  (:init (in p1 feed-1) (in p2 feed-2) (in p3 feed-3) (in junk bin)
         (free-gripper))
  (:goal (and (in p1 bin) (in p2 bin) (in p3 bin))))
