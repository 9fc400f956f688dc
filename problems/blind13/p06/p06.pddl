(define (problem p06)
  (:domain kuka-tower)
  (:objects b c - block
            drum - drum
            pad - area)
  (:init (in-area b pad) (in-area c pad)
         (clear b) (clear c) (clear drum) (handfree))
  (:goal (and (on b drum) (on c b))))
