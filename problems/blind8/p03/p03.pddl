;; xArm6: fetch the back flask from a narrow shelf slot with a top board;
;; the front flask must end where it started; a puck sits on the target spot.
(define (problem blind8-p03)
  (:domain blind8-fetch)
  (:objects flask-a flask-b puck - container
            slot-front slot-back dst aside - place)
  (:init (at flask-a slot-front) (at flask-b slot-back) (at puck dst)
         (empty-hand))
  (:goal (and (at flask-b dst) (at flask-a slot-front))))
